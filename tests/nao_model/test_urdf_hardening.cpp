// The URDF loader refuses absurd or nonsensical input with "file:line: what",
// before anything reaches ODE. Each case here is an input that crashed the
// simulator (ODE assertion, stack overflow) or was accepted silently before
// bad input is refused with file and line; the line asserted is the line of the offending element.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/nao_model/NaoBinding.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/nao_model/UrdfLines.hpp"
#include "tests/support/NaoV5Model.hpp"

using simswift::ModelError;
using simswift::RobotModel;

namespace {

using simswift::testing::readNaoV5Urdf;

int lineAt(const std::string& text, size_t pos) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

std::string urdfError(const std::string& xml) {
  try {
    // The model, then its libagent joints, as the runner checks them.
    const RobotModel m = RobotModel::loadUrdfString(xml, "bad.urdf");
    const simswift::NaoBinding nao(m);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

// Replaces the first `from` after the start of <tag name="name"> with `to`;
// returns the line of the replacement.
int replaceIn(std::string& xml, const std::string& tag, const std::string& name, const std::string& from,
              const std::string& to) {
  const size_t b = xml.find("<" + tag + " name=\"" + name + "\"");
  EXPECT_NE(b, std::string::npos);
  const size_t p = xml.find(from, b);
  EXPECT_NE(p, std::string::npos) << from;
  xml.replace(p, from.size(), to);
  return lineAt(xml, p);
}

void expectError(const std::string& xml, int line, const std::string& words) {
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(line) + ": ", 0), 0u) << err;
  EXPECT_NE(err.find(words), std::string::npos) << err;
}

}  // namespace

TEST(UrdfHardening, OverflowingAxisIsRefused) {
  // Crashed ODE (dxNormalize3): the axis's length overflows to inf.
  std::string xml = readNaoV5Urdf();
  const int line = replaceIn(xml, "joint", "LKneePitch", "<axis xyz=\"0 1 0\"/>", "<axis xyz=\"0 0 2e154\"/>");
  expectError(xml, line, "joint 'LKneePitch' <axis xyz>");
}

TEST(UrdfHardening, HugeInertialOriginAndInertiaAreRefused) {
  // Both crashed ODE (dxNormalize4) once stepped.
  std::string xml = readNaoV5Urdf();
  int line = replaceIn(xml, "link", "LTibia", "<origin xyz=\"", "<origin xyz=\"1e305 ");
  // "1e305 <old x>" is three numbers plus one: urdfdom refuses it or we do.
  EXPECT_EQ(urdfError(xml).rfind("bad.urdf:", 0), 0u) << urdfError(xml);
  xml = readNaoV5Urdf();
  const size_t b = xml.find("<link name=\"LTibia\"");
  const size_t o = xml.find("<origin xyz=\"", b);
  xml.replace(o, xml.find("\"", o + 13) - o + 1, "<origin xyz=\"1e305 0 0\"");
  line = lineAt(xml, o);
  expectError(xml, line, "<inertial><origin>: xyz");

  xml = readNaoV5Urdf();
  const size_t i = xml.find("ixx=\"", xml.find("<link name=\"LTibia\""));
  xml.replace(i, xml.find("\"", i + 5) - i + 1, "ixx=\"1e100\"");
  expectError(xml, lineAt(xml, i), "<inertia> has a value beyond");
}

TEST(UrdfHardening, AbsurdMassesAreRefused) {
  for (const char* m : {"1e-300", "1e300", "nan", "-1"}) {
    std::string xml = readNaoV5Urdf();
    const size_t b = xml.find("<link name=\"Head\"");
    const size_t p = xml.find("<mass value=\"", b);
    xml.replace(p, xml.find("/>", p) + 2 - p, std::string("<mass value=\"") + m + "\"/>");
    const std::string err = urdfError(xml);
    EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(lineAt(xml, p)) + ": ", 0), 0u) << m << ": " << err;
    EXPECT_NE(err.find("Head"), std::string::npos) << err;
  }
}

TEST(UrdfHardening, MissingInertiaAndNanOriginSayWhatIsWrong) {
  std::string xml = readNaoV5Urdf();
  const size_t b = xml.find("<link name=\"Head\"");
  const size_t p = xml.find("<inertia ", b);
  const int line = lineAt(xml, xml.find("<inertial>", b));
  xml.erase(p, xml.find("/>", p) + 2 - p);
  expectError(xml, line, "has no <inertia>");

  xml = readNaoV5Urdf();
  const size_t o = xml.find("<origin xyz=\"", b);
  xml.replace(o, xml.find("\"", o + 13) - o + 1, "<origin xyz=\"nan 0 0\"");
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(lineAt(xml, o)) + ": ", 0), 0u) << err;
  EXPECT_EQ(err.find("mass"), std::string::npos) << "a NaN origin is not a mass problem: " << err;
}

TEST(UrdfHardening, RHipYawPitchMustMimicLHipYawPitch) {
  std::string xml = readNaoV5Urdf();
  const size_t m = xml.find("<mimic joint=\"LHipYawPitch\"");
  ASSERT_NE(m, std::string::npos);
  const int joint_line = lineAt(xml, xml.find("<joint name=\"RHipYawPitch\""));
  xml.erase(m, xml.find("/>", m) + 2 - m);
  expectError(xml, joint_line, "RHipYawPitch");
  EXPECT_NE(urdfError(xml).find("mimic"), std::string::npos);
}

TEST(UrdfHardening, UnreadableCollisionGeometryIsRefused) {
  for (const char* size : {"nan 0.1 0.1", "inf 0.1 0.1", "0.1 0.1", "1e300 1 1"}) {
    std::string xml = readNaoV5Urdf();
    const size_t b = xml.find("<link name=\"LTibia\"");
    const size_t c = xml.find("<collision>", b);
    const size_t g = xml.find("<geometry>", c);
    xml.replace(g, xml.find("</geometry>", g) + 11 - g,
                std::string("<geometry><box size=\"") + size + "\"/></geometry>");
    const std::string err = urdfError(xml);
    // The <box> line (numbers that do not parse) or its <collision>'s (a bad size).
    EXPECT_TRUE(err.rfind("bad.urdf:" + std::to_string(lineAt(xml, c)) + ": ", 0) == 0 ||
                err.rfind("bad.urdf:" + std::to_string(lineAt(xml, g)) + ": ", 0) == 0)
        << size << ": " << err;
    EXPECT_NE(err.find("LTibia"), std::string::npos) << err;
  }
  std::string xml = readNaoV5Urdf();
  const size_t c = xml.find("<collision>", xml.find("<link name=\"LTibia\""));
  const size_t o = xml.find("<origin xyz=\"", c);
  xml.replace(o, xml.find("\"", o + 13) - o + 1, "<origin xyz=\"inf 0 0\"");
  EXPECT_EQ(urdfError(xml).rfind("bad.urdf:" + std::to_string(lineAt(xml, o)) + ": link 'LTibia'", 0), 0u)
      << urdfError(xml);
}

TEST(UrdfHardening, DeepNestingAndHugeFilesAreRefusedBeforeParsing) {
  // 100,000 levels overflowed the XML parser's stack after 10 s.
  std::string deep = "<robot name=\"x\">\n";
  for (int i = 0; i < 100000; ++i) deep += "<a>";
  deep += "\n</robot>";
  const std::string err = urdfError(deep);
  EXPECT_EQ(err.rfind("bad.urdf:2: ", 0), 0u) << err;
  EXPECT_NE(err.find("nested more than 32 deep"), std::string::npos) << err;

  std::string big = readNaoV5Urdf();
  big.insert(big.find("<robot"), std::string(simswift::UrdfLimits::kMaxBytes, ' '));
  EXPECT_NE(urdfError(big).find("MB limit"), std::string::npos) << urdfError(big).substr(0, 200);
}

TEST(UrdfHardening, DirectoryIsNotAUrdf) {
  try {
    RobotModel::loadUrdf(std::string(SIMSWIFT_SOURCE_DIR) + "/models");
    FAIL() << "a directory loaded";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("models:1: is a directory"), std::string::npos) << e.what();
  }
}

TEST(UrdfHardening, ParseErrorsCarryALine) {
  std::string xml = readNaoV5Urdf();
  const int line = replaceIn(xml, "joint", "LKneePitch", "effort=\"", "effort=\"abc");
  expectError(xml, line, "<limit effort=\"abc");
}

TEST(UrdfHardening, NulByteNearTheEndOfABigFileNamesItsLine) {
  // 3 MB of comment lines, then a NUL: refused at the NUL's line (the line
  // is counted in one pass; it was counted once per byte before).
  std::string xml = readNaoV5Urdf();
  const size_t end = xml.rfind("</robot>");
  std::string pad = "<!--\n";
  for (int i = 0; i < 42000; ++i) pad += std::string(70, 'x') + "\n";
  pad += "-->\n<link name=\"bad";
  pad += '\0';
  pad += "\"/>\n";
  xml.insert(end, pad);
  const size_t nul = xml.find('\0');
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(lineAt(xml, nul)) + ": ", 0), 0u) << err.substr(0, 200);
  EXPECT_NE(err.find("NUL byte"), std::string::npos) << err.substr(0, 200);
}

TEST(UrdfHardening, ManyAttributesOnOneElementAreRefusedAtItsLine) {
  // 1 MB of attributes on <robot> took TinyXML 59 s (each attribute is
  // looked up among the ones before it); refused by the pre-pass now.
  std::string xml = readNaoV5Urdf();
  const size_t robot = xml.find("<robot");
  std::string attrs;
  for (int k = 0; k < 65; ++k) attrs += "\n    a" + std::to_string(k) + "=\"0\"";
  xml.insert(robot + 6, attrs);
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(lineAt(xml, robot)) + ": ", 0), 0u) << err.substr(0, 200);
  EXPECT_NE(err.find("<robot> has more than 64 attributes"), std::string::npos) << err.substr(0, 200);

  // 64 unknown attributes are not an error of this kind (urdfdom ignores them).
  xml = readNaoV5Urdf();
  attrs.clear();
  for (int k = 0; k < 63; ++k) attrs += " a" + std::to_string(k) + "=\"0\"";
  xml.insert(xml.find("<robot") + 6, attrs);
  EXPECT_EQ(urdfError(xml), "");
}

TEST(UrdfHardening, MoreElementsThanTheLimitAreRefusedAtTheFirstOneOver) {
  std::string xml = readNaoV5Urdf();
  const size_t end = xml.rfind("</robot>");
  // Count the shipped file's elements the way the limit does: every opening
  // tag outside comments (the shipped file has no CDATA).
  int shipped = 0;
  for (size_t p = xml.find('<'); p < end; p = xml.find('<', p + 1)) {
    if (xml.compare(p, 4, "<!--") == 0) {
      p = xml.find("-->", p);
      continue;
    }
    if (xml[p + 1] != '/' && xml[p + 1] != '?' && xml[p + 1] != '!') ++shipped;
  }
  ASSERT_GT(shipped, 100);
  ASSERT_LT(shipped, simswift::UrdfLimits::kMaxElements);
  std::string pad;
  const int extra = simswift::UrdfLimits::kMaxElements - shipped + 1;  // the last one is over
  for (int k = 0; k < extra; ++k) pad += "<material name=\"m" + std::to_string(k) + "\"/>\n";
  xml.insert(end, pad);
  const int over = lineAt(xml, end) + extra - 1;
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(over) + ": ", 0), 0u) << err.substr(0, 200);
  EXPECT_NE(err.find("more than 16384 elements"), std::string::npos) << err.substr(0, 200);
}

TEST(UrdfHardening, UrdfdomErrorsNamingAJointGetItsLine) {
  // urdfdom's message names the missing link and the joint in [brackets];
  // the line is the joint's (the names are looked up in one pass).
  std::string xml = readNaoV5Urdf();
  const int line = lineAt(xml, xml.find("<joint name=\"LKneePitch\""));
  replaceIn(xml, "joint", "LKneePitch", "<child link=\"", "<child link=\"NoSuchLink");
  const std::string err = urdfError(xml);
  EXPECT_EQ(err.rfind("bad.urdf:" + std::to_string(line) + ": ", 0), 0u) << err;
  EXPECT_NE(err.find("NoSuchLink"), std::string::npos) << err;
}

TEST(UrdfHardening, OversizeFileIsRefusedNamingTheLimit) {
  // Through the file loader: refused from the file's size, before reading.
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "simswift_test_oversize.urdf";
  {
    std::ofstream out(path);
    out << readNaoV5Urdf();
    out << std::string(simswift::UrdfLimits::kMaxBytes, '\n');
  }
  try {
    RobotModel::loadUrdf(path.string());
    ADD_FAILURE() << "a 4 MB + 25 KB URDF loaded";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ":1: URDF is ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("more than the 4 MB limit"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

// Two <child> lines swapped make a kinematic loop (RPelvis -> ... -> RTibia
// -> RPelvis): refused, and freed (urdfdom keeps a loop's links alive through
// their child pointers; the sanitizer build's leak check fails this test if
// the loader does not break the cycle). Found by the loader fuzzer.
TEST(UrdfHardening, KinematicLoopIsRefusedAndFreed) {
  std::string xml = readNaoV5Urdf();
  const size_t a = xml.find("<child link=\"RPelvis\"/>"), b = xml.find("<child link=\"RTibia\"/>");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  xml.replace(std::max(a, b), std::string(a > b ? "<child link=\"RPelvis\"/>" : "<child link=\"RTibia\"/>").size(),
              a > b ? "<child link=\"RTibia\"/>" : "<child link=\"RPelvis\"/>");
  xml.replace(std::min(a, b), std::string(a < b ? "<child link=\"RPelvis\"/>" : "<child link=\"RTibia\"/>").size(),
              a < b ? "<child link=\"RTibia\"/>" : "<child link=\"RPelvis\"/>");
  EXPECT_NE(urdfError(xml).find("bad.urdf:"), std::string::npos) << urdfError(xml);
  EXPECT_NE(urdfError(xml).find("not connected to the root link"), std::string::npos) << urdfError(xml);
}
