#include "sim/record/Schemas.hpp"

#include <map>
#include <stdexcept>

namespace simswift::record {
namespace {

// Building blocks, spliced into the schemas below.
const std::string kTime =
    R"({"type":"object","title":"time","properties":{"sec":{"type":"integer","minimum":0},"nsec":{"type":"integer","minimum":0,"maximum":999999999}}})";
const std::string kVec3 =
    R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"}}})";
const std::string kQuat =
    R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}})";
const std::string kPose = R"({"type":"object","properties":{"position":)" + kVec3 + R"(,"orientation":)" + kQuat + "}}";
const std::string kColor =
    R"({"type":"object","properties":{"r":{"type":"number"},"g":{"type":"number"},"b":{"type":"number"},"a":{"type":"number"}}})";
const std::string kNumbers = R"({"type":"array","items":{"type":"number"}})";
const std::string kStrings = R"({"type":"array","items":{"type":"string"}})";

std::string object(const std::string& title, const std::string& properties) {
  return R"({"type":"object","title":")" + title + R"(","properties":{)" + properties + "}}";
}
std::string array(const std::string& items) { return R"({"type":"array","items":)" + items + "}"; }

const std::map<std::string, std::string>& schemas() {
  static const std::map<std::string, std::string> all = [] {
    std::map<std::string, std::string> m;
    const std::string transform =
        object("foxglove.FrameTransform", R"("timestamp":)" + kTime + R"(,"parent_frame_id":{"type":"string"},)" +
                                              R"("child_frame_id":{"type":"string"},"translation":)" + kVec3 +
                                              R"(,"rotation":)" + kQuat);
    m["foxglove.FrameTransforms"] = object("foxglove.FrameTransforms", R"("transforms":)" + array(transform));
    const std::string shape_common = R"("pose":)" + kPose + R"(,"color":)" + kColor;
    const std::string cube = object("foxglove.CubePrimitive", shape_common + R"(,"size":)" + kVec3);
    const std::string sphere = object("foxglove.SpherePrimitive", shape_common + R"(,"size":)" + kVec3);
    const std::string cylinder =
        object("foxglove.CylinderPrimitive",
               shape_common + R"(,"size":)" + kVec3 + R"(,"bottom_scale":{"type":"number"},"top_scale":{"type":"number"})");
    const std::string line = object(
        "foxglove.LinePrimitive",
        R"("type":{"type":"integer","description":"0 LINE_STRIP, 1 LINE_LOOP, 2 LINE_LIST"},"pose":)" + kPose +
            R"(,"thickness":{"type":"number"},"scale_invariant":{"type":"boolean"},"points":)" + array(kVec3) +
            R"(,"color":)" + kColor + R"(,"colors":)" + array(kColor) +
            R"(,"indices":{"type":"array","items":{"type":"integer"}})");
    const std::string entity = object(
        "foxglove.SceneEntity",
        R"("timestamp":)" + kTime + R"(,"frame_id":{"type":"string"},"id":{"type":"string"},"lifetime":)" + kTime +
            R"(,"frame_locked":{"type":"boolean"},"metadata":{"type":"array"},"arrows":{"type":"array"},"cubes":)" +
            array(cube) + R"(,"spheres":)" + array(sphere) + R"(,"cylinders":)" + array(cylinder) + R"(,"lines":)" +
            array(line) + R"(,"triangles":{"type":"array"},"texts":{"type":"array"},"models":{"type":"array"})");
    m["foxglove.SceneUpdate"] =
        object("foxglove.SceneUpdate", R"("deletions":{"type":"array"},"entities":)" + array(entity));
    m["foxglove.CompressedImage"] =
        object("foxglove.CompressedImage", R"("timestamp":)" + kTime +
                                               R"(,"frame_id":{"type":"string"},"data":{"type":"string","contentEncoding":"base64"},)" +
                                               R"("format":{"type":"string"})");
    m["foxglove.Log"] = object(
        "foxglove.Log",
        R"("timestamp":)" + kTime +
            R"(,"level":{"type":"integer","description":"0 UNKNOWN, 1 DEBUG, 2 INFO, 3 WARNING, 4 ERROR, 5 FATAL"},)" +
            R"("message":{"type":"string"},"name":{"type":"string"},"file":{"type":"string"},"line":{"type":"integer"})");
    m["simswift.JointState"] = object(
        "simswift.JointState", R"("timestamp":)" + kTime + R"(,"name":)" + kStrings +
                                   R"(,"position":)" + kNumbers + R"(,"command":)" + kNumbers +
                                   R"(,"stiffness":)" + kNumbers);
    m["simswift.Sensors"] = object(
        "simswift.Sensors",
        R"("timestamp":)" + kTime + R"(,"fsr_left":)" + kNumbers + R"(,"fsr_right":)" + kNumbers +
            R"(,"accelerometer":)" + kVec3 + R"(,"gyroscope":)" + kVec3 +
            R"(,"angle":{"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"}}},"sonar":)" +
            R"({"type":"object","properties":{"left":)" + kNumbers + R"(,"right":)" + kNumbers + "}}" +
            R"(,"battery":{"type":"object","properties":{"charge":{"type":"number"},"current":{"type":"number"}}})" +
            R"(,"buttons":{"type":"object","properties":{"chest":{"type":"number"},"head_front":{"type":"number"},)" +
            R"("head_middle":{"type":"number"},"head_rear":{"type":"number"}}})" +
            R"(,"bumpers":{"type":"object","properties":{"left_left":{"type":"number"},"left_right":{"type":"number"},)" +
            R"("right_left":{"type":"number"},"right_right":{"type":"number"}}})");
    m["simswift.TeamMessage"] = object(
        "simswift.TeamMessage",
        R"("timestamp":)" + kTime +
            R"(,"from":{"type":"integer","description":"sending robot's index"},)" +
            R"("to":{"type":"integer","description":"receiving robot's index; -1: sent to the team"},)" +
            R"("sent":)" + kTime + R"(,"bytes":{"type":"string","contentEncoding":"base64"},"size":{"type":"integer"})");
    m["simswift.Belief"] = object(
        "simswift.Belief",
        R"("timestamp":)" + kTime +
            R"(,"ball":{"type":["object","null"],"properties":{"x":{"type":"number"},"y":{"type":"number"}}},)" +
            R"("pose":{"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},"theta":{"type":"number"}}},)" +
            R"("behaviour":{"type":"string"})");
    return m;
  }();
  return all;
}

}  // namespace

const std::string& jsonSchema(const std::string& name) {
  const auto it = schemas().find(name);
  if (it == schemas().end()) throw std::out_of_range("no recording schema " + name);
  return it->second;
}

}  // namespace simswift::record
