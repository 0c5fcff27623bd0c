#include "sim/record/Recorder.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/SharedNames.hpp"
#include "sim/game/GameController.hpp"
#include "sim/record/Schemas.hpp"
#include "sim/runner/Bodies.hpp"
#include "sim/runner/Runner.hpp"

namespace simswift::record {

namespace al = common::libagent;
namespace S = common::libagent::Sensors;

namespace {

constexpr const char* kJson = "json";
constexpr const char* kJsonSchema = "jsonschema";

std::string robotName(int i) { return "robot" + std::to_string(i); }

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string number(double v) {
  Json j;
  j.num(v);
  return j.text();
}

}  // namespace

const char* simswiftVersion() { return SIMSWIFT_VERSION; }
const char* simswiftCommit() { return SIMSWIFT_COMMIT; }

Recorder::Recorder(const std::string& path, RecordOptions options)
    : options_(std::move(options)), writer_(path, std::string("simswift ") + simswiftVersion()) {
  if (!(options_.rate_hz > 0 && options_.rate_hz <= 1000))
    throw RecordError("recording " + path + ": rate " + number(options_.rate_hz) + " Hz must be in (0, 1000]");
}

Recorder::~Recorder() = default;  // the writer closes the file

void Recorder::finish() { writer_.close(); }

// The metadata, every channel (so a streaming reader sees them all before
// any message) and the scene at t = 0.
void Recorder::begin(const runner::Runner& r) {
  if (begun_) return;
  begun_ = true;
  const runner::Scenario& sc = r.scenario();
  const World& w = r.world();
  McapWriter::StringMap meta = {{"scenario", sc.source},
                                {"scenario_text", fileText(sc.source)},
                                {"seed", std::to_string(sc.seed)},
                                {"commit", simswiftCommit()},
                                {"simswift_version", simswiftVersion()},
                                {"tick_ns", std::to_string(w.tickUs() * 1000)},
                                {"rate_hz", number(options_.rate_hz)},
                                {"duration_s", number(sc.duration)}};
  // robots: one JSON array, [{id, team, player, body, links: [...]}, ...]
  Json robots;
  robots.openArray();
  for (int i = 0; i < r.numRobots(); ++i) {
    const runner::RobotSpec& spec = sc.robots[i];
    robots.open().key("id").str(robotName(i)).key("team").integer(spec.team).key("player").integer(spec.player);
    robots.key("body").str(spec.body == bridge::BodyInterface::Lola ? "V6" : "V5");
    robots.key("links").openArray();
    for (const LinkSpec& l : w.robot(i).model().links()) robots.str(l.name);
    robots.closeArray().close();
  }
  robots.closeArray();
  meta.push_back({"robots", robots.text()});
  writer_.addMetadata("simswift", meta);

  auto channel = [&](const std::string& schema, const std::string& topic) {
    const uint16_t s = writer_.addSchema(schema, kJsonSchema, jsonSchema(schema));
    return writer_.addChannel(s, topic, kJson);
  };
  // One schema record per channel keeps the writer simple; schemas shared
  // by robots are written once and reused.
  const uint16_t joint_schema = writer_.addSchema("simswift.JointState", kJsonSchema, jsonSchema("simswift.JointState"));
  const uint16_t sensor_schema = writer_.addSchema("simswift.Sensors", kJsonSchema, jsonSchema("simswift.Sensors"));
  const uint16_t team_schema = writer_.addSchema("simswift.TeamMessage", kJsonSchema, jsonSchema("simswift.TeamMessage"));
  tf_ = channel("foxglove.FrameTransforms", "/tf");
  scene_ = channel("foxglove.SceneUpdate", "/scene");
  events_ = channel("foxglove.Log", "/events");
  team_sent_ = writer_.addChannel(team_schema, "/team/sent", kJson);
  team_delivered_ = writer_.addChannel(team_schema, "/team/delivered", kJson);
  frame_ids_.clear();
  for (int i = 0; i < r.numRobots(); ++i) {
    RobotChannels c{};
    c.joints = writer_.addChannel(joint_schema, "/" + robotName(i) + "/joints", kJson);
    c.sensors = writer_.addChannel(sensor_schema, "/" + robotName(i) + "/sensors", kJson);
    robots_.push_back(c);
    std::vector<std::string> ids;
    for (const LinkSpec& l : w.robot(i).model().links()) ids.push_back(robotName(i) + "/" + l.name);
    frame_ids_.push_back(std::move(ids));
    tags_.push_back(al::robotTag(sc.robots[i].team, sc.robots[i].player));
    falls_.push_back(0);
    pushes_.push_back(0);
    penalties_.push_back(0);
  }
  writeScene(r);
}

void Recorder::observe(const runner::Runner& r, int64_t t_us) {
  begin(r);
  const uint64_t t_ns = static_cast<uint64_t>(t_us) * 1000;
  last_t_ns_ = t_ns;
  // Sample k is due once t_us * rate / 1e6 reaches k (the first tick: 0).
  const auto sample = static_cast<int64_t>(static_cast<double>(t_us) * options_.rate_hz / 1e6 + 1e-9);
  if (sample > last_sample_) {
    last_sample_ = sample;
    writeSample(r, t_ns);
  }
  writeEvents(r, t_ns);
  writeTeam(r, t_ns);
}

// A message naming a robot as the runner does ("robot t19p2: ...") is
// prefixed "robot<i>: " (the recording's name for it).
void Recorder::event(LogLevel level, const std::string& kind, const std::string& message, const std::string& file,
                     int line) {
  for (size_t i = 0; i < tags_.size(); ++i)
    if (message.find("robot " + tags_[i]) != std::string::npos) {
      log(last_t_ns_, level, kind, robotName(static_cast<int>(i)) + ": " + message, file, line);
      return;
    }
  log(last_t_ns_, level, kind, message, file, line);
}

void Recorder::log(uint64_t t_ns, LogLevel level, const std::string& kind, const std::string& message,
                   const std::string& file, int line) {
  if (!begun_) return;  // nothing observed yet: no channels
  json_.clear();
  json_.open().key("timestamp").time(t_ns).key("level").integer(static_cast<int>(level));
  json_.key("message").str(message).key("name").str(kind).key("file").str(file).key("line").integer(line).close();
  writer_.write(events_, t_ns, json_.text());
}

// The poses of every link and the ball (/tf), each robot's joints and sensors.
void Recorder::writeSample(const runner::Runner& r, uint64_t t_ns) {
  const World& w = r.world();
  json_.clear();
  json_.open().key("transforms").openArray();
  for (int i = 0; i < r.numRobots(); ++i) {
    const RobotBody& body = w.robot(i);
    const int links = static_cast<int>(frame_ids_[i].size());
    for (int l = 0; l < links; ++l) {
      const Eigen::Isometry3d p = body.linkPose(l);
      const Eigen::Quaterniond q(p.rotation());
      json_.open().key("timestamp").time(t_ns).key("parent_frame_id").str("world");
      json_.key("child_frame_id").str(frame_ids_[i][l]);
      json_.key("translation").vec3(p.translation().x(), p.translation().y(), p.translation().z());
      json_.key("rotation").quat(q.x(), q.y(), q.z(), q.w()).close();
    }
  }
  if (w.hasBall()) {
    const Eigen::Vector3d b = w.ballPosition();
    const Eigen::Quaterniond q = w.ballOrientation();
    json_.open().key("timestamp").time(t_ns).key("parent_frame_id").str("world").key("child_frame_id").str("ball");
    json_.key("translation").vec3(b.x(), b.y(), b.z()).key("rotation").quat(q.x(), q.y(), q.z(), q.w()).close();
  }
  json_.closeArray().close();
  writer_.write(tf_, t_ns, json_.text());

  for (int i = 0; i < r.numRobots(); ++i) {
    const al::SensorValues& v = r.lastSensors(i);
    const al::ActuatorCommand& c = r.lastCommand(i);
    json_.clear();
    json_.open().key("timestamp").time(t_ns).key("name").openArray();
    for (int j = 0; j < al::kNumJoints; ++j) json_.str(al::Joints::kNames[j]);
    json_.closeArray().key("position").openArray();
    for (int j = 0; j < al::kNumJoints; ++j) json_.num(v.joints.angles[j]);
    json_.closeArray().key("command").openArray();
    for (int j = 0; j < al::kNumJoints; ++j) json_.num(c.joints.angles[j]);
    json_.closeArray().key("stiffness").openArray();
    for (int j = 0; j < al::kNumJoints; ++j) json_.num(c.joints.stiffnesses[j]);
    json_.closeArray().close();
    writer_.write(robots_[i].joints, t_ns, json_.text());

    const float* s = v.sensors;
    json_.clear();
    json_.open().key("timestamp").time(t_ns).key("fsr_left").openArray();
    for (int k = S::LFoot_FSR_FrontLeft; k <= S::LFoot_FSR_RearRight; ++k) json_.num(s[k]);
    json_.closeArray().key("fsr_right").openArray();
    for (int k = S::RFoot_FSR_FrontLeft; k <= S::RFoot_FSR_RearRight; ++k) json_.num(s[k]);
    json_.closeArray();
    json_.key("accelerometer")
        .vec3(s[S::InertialSensor_AccelerometerX], s[S::InertialSensor_AccelerometerY],
              s[S::InertialSensor_AccelerometerZ]);
    json_.key("gyroscope")
        .vec3(s[S::InertialSensor_GyroscopeX], s[S::InertialSensor_GyroscopeY], s[S::InertialSensor_GyroscopeZ]);
    json_.key("angle").open().key("x").num(s[S::InertialSensor_AngleX]).key("y").num(s[S::InertialSensor_AngleY]);
    json_.close().key("sonar").open().key("left").openArray();
    for (int k = 0; k < al::kNumSonars / 2; ++k) json_.num(v.sonar[k]);
    json_.closeArray().key("right").openArray();
    for (int k = al::kNumSonars / 2; k < al::kNumSonars; ++k) json_.num(v.sonar[k]);
    json_.closeArray().close();
    json_.key("battery").open().key("charge").num(s[S::Battery_Charge]).key("current").num(s[S::Battery_Current]);
    json_.close().key("buttons").open().key("chest").num(s[S::ChestBoard_Button]);
    json_.key("head_front").num(s[S::Head_Touch_Front]).key("head_middle").num(s[S::Head_Touch_Middle]);
    json_.key("head_rear").num(s[S::Head_Touch_Rear]).close();
    json_.key("bumpers").open().key("left_left").num(s[S::LFoot_Bumper_Left]);
    json_.key("left_right").num(s[S::LFoot_Bumper_Right]).key("right_left").num(s[S::RFoot_Bumper_Left]);
    json_.key("right_right").num(s[S::RFoot_Bumper_Right]).close();
    json_.close();
    writer_.write(robots_[i].sensors, t_ns, json_.text());
  }
}

// Falls (the runner's fall detector), pushes (the scenario's, as applied),
// penalties and game states (the GameController), each as it happens.
void Recorder::writeEvents(const runner::Runner& r, uint64_t t_ns) {
  for (int i = 0; i < r.numRobots(); ++i) {
    const runner::FallDetector& f = r.robotFall(i);
    if (f.falls > falls_[i]) {
      falls_[i] = f.falls;
      log(t_ns, LogLevel::Warning, "fall",
          robotName(i) + ": fell (torso below " + number(runner::FallDetector::kFallHeight) + " m; fall " +
              std::to_string(f.falls) + (f.contact_falls > 0 ? ", robot contact before it" : "") + ")");
    }
    const int pushed = r.pushesApplied(i);
    for (; pushes_[i] < pushed; ++pushes_[i]) {
      const runner::RobotSpec::Push& p = r.scenario().robots[i].pushes[pushes_[i]];
      log(t_ns, LogLevel::Info, "push",
          robotName(i) + ": pushed (" + number(p.jx) + ", " + number(p.jy) + ") N*s at the torso");
    }
    const auto penalty = static_cast<int>(r.gameController().penalty(i));
    if (penalty != penalties_[i]) {
      const bool on = penalty != static_cast<int>(game::Penalty::None);
      log(t_ns, on ? LogLevel::Warning : LogLevel::Info, "penalty",
          robotName(i) + ": " +
              (on ? std::string("penalised ") + game::penaltyName(static_cast<game::Penalty>(penalty))
                  : std::string("unpenalised")));
      penalties_[i] = penalty;
    }
  }
  const auto state = static_cast<int>(r.gameController().state());
  if (state != game_state_) {
    game_state_ = state;
    log(t_ns, LogLevel::Info, "game_state", std::string("game state ") + game::stateName(r.gameController().state()));
  }
}

void Recorder::writeTeam(const runner::Runner& r, uint64_t t_ns) {
  const network::TeamNetwork& net = r.teamNetwork();
  for (const bool delivered : {false, true}) {
    for (const network::Delivery& d : delivered ? net.lastDelivered() : net.lastSent()) {
      json_.clear();
      json_.open().key("timestamp").time(t_ns).key("from").integer(d.from).key("to").integer(d.to);
      json_.key("sent").time(static_cast<uint64_t>(d.sent_us) * 1000);
      json_.key("bytes").base64(d.bytes.data(), d.bytes.size()).key("size").integer(static_cast<int64_t>(d.bytes.size()));
      json_.close();
      writer_.write(delivered ? team_delivered_ : team_sent_, t_ns, json_.text());
    }
  }
}

namespace {

// A shape as Foxglove's primitives: pose in the entity's frame, colour.
void pose(Json& j, const Pose3& p) {
  j.key("pose").open().key("position").vec3(p.xyz.x(), p.xyz.y(), p.xyz.z());
  j.key("orientation").quat(p.rotation.x(), p.rotation.y(), p.rotation.z(), p.rotation.w()).close();
}
void color(Json& j, const Eigen::Vector4d& c) {
  j.key("color").open().key("r").num(c[0]).key("g").num(c[1]).key("b").num(c[2]).key("a").num(c[3]).close();
}

struct Primitives {
  std::vector<std::pair<ShapeSpec, Eigen::Vector4d>> cubes, spheres, cylinders;
  void add(const ShapeSpec& s, const Eigen::Vector4d& rgba) {
    switch (s.type) {
      case ShapeType::Box: cubes.push_back({s, rgba}); break;
      case ShapeType::Sphere: spheres.push_back({s, rgba}); break;
      case ShapeType::Cylinder: cylinders.push_back({s, rgba}); break;
      case ShapeType::Capsule: {  // a cylinder and a sphere at each end
        cylinders.push_back({s, rgba});
        for (const double end : {-0.5, 0.5}) {
          ShapeSpec cap = s;
          cap.type = ShapeType::Sphere;
          cap.origin.xyz = s.origin.xyz + s.origin.rotation * Eigen::Vector3d(0, 0, end * s.length);
          spheres.push_back({cap, rgba});
        }
        break;
      }
      case ShapeType::Mesh: break;  // no primitive: the collision shapes stand for it
    }
  }
};

void entity(Json& j, const std::string& frame, const std::string& id, const Primitives& p,
            const std::function<void(Json&)>& lines = {}) {
  j.open().key("timestamp").time(0).key("frame_id").str(frame).key("id").str(id);
  j.key("lifetime").time(0).key("frame_locked").boolean(true).key("metadata").openArray().closeArray();
  j.key("arrows").openArray().closeArray();
  j.key("cubes").openArray();
  for (const auto& [s, c] : p.cubes) {
    j.open();
    pose(j, s.origin);
    j.key("size").vec3(s.size.x(), s.size.y(), s.size.z());
    color(j, c);
    j.close();
  }
  j.closeArray().key("spheres").openArray();
  for (const auto& [s, c] : p.spheres) {
    j.open();
    pose(j, s.origin);
    j.key("size").vec3(2 * s.radius, 2 * s.radius, 2 * s.radius);
    color(j, c);
    j.close();
  }
  j.closeArray().key("cylinders").openArray();
  for (const auto& [s, c] : p.cylinders) {  // along the shape's z, as URDF's and Foxglove's
    j.open();
    pose(j, s.origin);
    j.key("size").vec3(2 * s.radius, 2 * s.radius, s.length).key("bottom_scale").num(1).key("top_scale").num(1);
    color(j, c);
    j.close();
  }
  j.closeArray().key("lines").openArray();
  if (lines) lines(j);
  j.closeArray();
  j.key("triangles").openArray().closeArray().key("texts").openArray().closeArray();
  j.key("models").openArray().closeArray().close();
}

Eigen::Vector4d rgba(double r, double g, double b, double a = 1) { return {r, g, b, a}; }

}  // namespace

// Once, at t = 0: every robot link's shapes in its own frame (collision
// shapes grey, visual primitives in their colours), the field (lines,
// goals) in "world" and the ball in "ball".
void Recorder::writeScene(const runner::Runner& r) {
  const World& w = r.world();
  json_.clear();
  json_.open().key("deletions").openArray().closeArray().key("entities").openArray();
  for (int i = 0; i < r.numRobots(); ++i) {
    const auto& links = w.robot(i).model().links();
    for (size_t l = 0; l < links.size(); ++l) {
      Primitives p;
      for (const ShapeSpec& s : links[l].collisions) p.add(s, rgba(0.75, 0.75, 0.78, 1));
      for (const ShapeSpec& s : links[l].visuals) p.add(s, s.rgba);
      entity(json_, frame_ids_[i][l], frame_ids_[i][l], p);
    }
  }
  // The field: carpet, lines (LINE_LIST at 1 cm over the carpet), goals.
  const FieldConfig& f = w.field();
  Primitives field;
  ShapeSpec carpet;
  carpet.type = ShapeType::Box;
  carpet.size = Eigen::Vector3d(f.carpetLength(), f.carpetWidth(), 0.002);
  carpet.origin.xyz = Eigen::Vector3d(0, 0, -0.001);
  field.add(carpet, rgba(0.1, 0.45, 0.15));
  const GoalConfig& g = f.goal;
  const double post_r = g.post_diameter / 2;
  const double post_y = g.inner_width / 2 + post_r;  // post centres, m
  for (const double side : {-1.0, 1.0}) {
    const double x = side * (f.length / 2 + post_r);
    for (const double y : {-post_y, post_y}) {
      ShapeSpec post;
      post.type = ShapeType::Cylinder;
      post.radius = post_r;
      post.length = g.post_height;
      post.origin.xyz = Eigen::Vector3d(x, y, g.post_height / 2);
      field.add(post, rgba(1, 1, 1));
    }
    ShapeSpec bar;  // the crossbar, along y
    bar.type = ShapeType::Cylinder;
    bar.radius = post_r;
    bar.length = 2 * post_y;
    bar.origin.xyz = Eigen::Vector3d(x, 0, g.post_height - post_r);
    bar.origin.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
    field.add(bar, rgba(1, 1, 1));
  }
  entity(json_, "world", "field", field, [&](Json& j) {
    const Pose3 origin;
    auto open_lines = [&](int type, double width) {
      j.open().key("type").integer(type);
      pose(j, origin);
      j.key("thickness").num(width).key("scale_invariant").boolean(false).key("points").openArray();
    };
    auto close_lines = [&] {
      j.closeArray();
      color(j, rgba(1, 1, 1));
      j.key("colors").openArray().closeArray().key("indices").openArray().closeArray().close();
    };
    constexpr double z = 0.01;  // m over the carpet
    for (const LineSegment& s : f.lines) {
      open_lines(2, s.width);
      j.vec3(s.ax, s.ay, z).vec3(s.bx, s.by, z);
      close_lines();
    }
    for (const LineCircle& c : f.circles) {
      open_lines(1, c.width);
      for (int k = 0; k < 48; ++k) {
        const double a = 2 * M_PI * k / 48;
        j.vec3(c.cx + c.radius * std::cos(a), c.cy + c.radius * std::sin(a), z);
      }
      close_lines();
    }
    for (const LineCross& c : f.crosses) {
      open_lines(2, c.width);
      j.vec3(c.x - c.size / 2, c.y, z).vec3(c.x + c.size / 2, c.y, z);
      j.vec3(c.x, c.y - c.size / 2, z).vec3(c.x, c.y + c.size / 2, z);
      close_lines();
    }
  });
  if (w.hasBall()) {
    Primitives ball;
    ShapeSpec s;
    s.type = ShapeType::Sphere;
    s.radius = f.ball.diameter / 2;
    ball.add(s, rgba(1, 0.4, 0));
    entity(json_, "ball", "ball", ball);
  }
  json_.closeArray().close();
  writer_.write(scene_, 0, json_.text());
}

}  // namespace simswift::record
