#include "sim/lola/LolaBody.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "common/libagent/Inertial.hpp"
#include "common/lola/Slots.hpp"

namespace simswift::lola {

namespace al = common::libagent;
namespace S = al::Sensors;
using common::libagent::SyncMode;

namespace {

uint8_t status(float temperature, const LolaBodyOptions& o) {
  if (temperature >= o.status_critical) return 3;
  if (temperature >= o.status_very_hot) return 2;
  if (temperature >= o.status_hot) return 1;
  return 0;
}

}  // namespace

SensorPacket toLolaPacket(const al::SensorValues& v, const LolaBodyOptions& options) {
  SensorPacket p;
  for (int j = 0; j < al::kNumJoints; ++j) {
    const int l = lolaJointOf(j);
    p.position[l] = v.joints.angles[j];
    p.stiffness[l] = std::max(0.f, v.joints.stiffnesses[j]);  // libagent's -1 (off) is LoLA's 0
    p.temperature[l] = v.joints.temperatures[j];
    p.current[l] = v.joints.currents[j];
    p.status[l] = status(v.joints.temperatures[j], options);
  }
  const float* s = v.sensors;
  // Inertial: the slots hold the V5's signs (common/libagent/Inertial.hpp);
  // back to the physical body rate w and specific force f, then with LoLA's
  // signs (common/lola/Protocol.hpp: the gyroscope +w, the accelerometer -f).
  for (int a = 0; a < 3; ++a) {
    const double w = al::inertial::kGyroscopeSign[a] * s[S::InertialSensor_GyroscopeX + a];
    const double f = al::inertial::kAccelerometerSign[a] * s[S::InertialSensor_AccelerometerX + a];
    p.gyroscope[a] = static_cast<float>(kGyroscopeSign[a] * w);
    p.accelerometer[a] = static_cast<float>(kAccelerometerSign[a] * f);
  }
  p.angles = {s[S::InertialSensor_AngleX], s[S::InertialSensor_AngleY]};  // same convention on both
  // FSR, Touch, Battery, Sonar: from the V5's slots (common/lola/Slots.hpp,
  // the mapping the robot program's client reads them back with). The
  // hands' touch sensors are not simulated (0): nothing touches them.
  for (int i = 0; i < kNumFsrs; ++i) p.fsr[i] = s[kFsrSlots[i]];  // kg, as the V5's slots
  for (int i = 0; i < kNumTouch; ++i) p.touch[i] = kTouchSlots[i] == kNoSensorSlot ? 0.f : s[kTouchSlots[i]];
  for (int i = 0; i < 2; ++i) p.sonar[i] = v.sonar[kSonarEchoes[i]];  // m
  // Battery: charge and current from the battery model. Status 0: no bits
  // set (not charging; a real V6 sends a 16-bit field as a float, e.g.
  // -32552 = 0x80D8 with the charging bit 0x80 on a robot being charged:
  // docs/lola.md). Its temperature is not modelled: an assumed 30 deg C.
  for (int i = 0; i < kNumBattery; ++i) p.battery[i] = kBatterySlots[i] == kNoSensorSlot ? 0.f : s[kBatterySlots[i]];
  p.battery[BatteryTemperature] = 30.f;
  p.robot_config = options.robot_config;
  return p;
}

LolaBody::LolaBody(int team, int player, const al::JointValues& initial, LolaBodyOptions options)
    : BodySide(al::robotTag(team, player)),
      options_(std::move(options)),
      server_(options_.socket_path, options_.decoder),
      objects_(std::make_unique<bridge::BodyHost>(
          team, player, options_.named ? bridge::BodyHost::Mode::Named : bridge::BodyHost::Mode::InProcess, initial,
          bridge::BodyHostOptions{false, options_.images})) {
  for (int j = 0; j < al::kNumJoints; ++j) position_[lolaJointOf(j)] = initial.angles[j];
  stiffness_.fill(0.f);  // limp until the program sends Stiffness
}

LolaBody::~LolaBody() = default;

std::string LolaBody::attachHint() const {
  return "start its LoLA program so that it connects to " + server_.path() + " (the reference program: " +
         "`simswift-agent --team " + std::to_string(objects_->team()) + " --player " +
         std::to_string(objects_->player()) + " --lola " + server_.path() +
         "`; one that opens /tmp/robocup, in the robot's view: `simswift attach --team " +
         std::to_string(objects_->team()) + " --player " + std::to_string(objects_->player()) + " -- PROGRAM`)";
}

// A launched program has a mount namespace of its own in which /tmp/robocup
// is this robot's socket (ProgramProcess): {socket} is the path it sees.
std::map<std::string, std::string> LolaBody::placeholders() const {
  return {{"socket", std::string(kDefaultSocketPath)}};
}

bool LolaBody::publishSensors(const al::SensorValues& values, int64_t /*sim_time_us*/, int64_t tick) {
  tick_ = tick;
  packet_ = encodeSensorPacket(toLolaPacket(values, options_));
  answered_ = false;
  // Sent now to a connected client (a program whose steps run on the
  // simulator's thread reads it in its step), and an answer taken if one is
  // already there. Lock-step then waits for it (waitAnswer; a client that
  // connects later gets this packet there); free-running does not.
  const Exchange e = server_.exchange(packet_, std::chrono::milliseconds(0));
  sent_ = e.status != Exchange::Status::NoClient;
  take(e);  // a client dropped: not sent after all
  return sent_;
}

bool LolaBody::waitAnswer(double timeout_s) {
  if (answered_) return true;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  while (!answered_) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return false;
    // A new connection (a program restarted by hand while the old one
    // hangs) replaces the old one: it gets this cycle's packet.
    const int accepted = server_.clientsAccepted();
    if (sent_ && server_.acceptPending() && server_.clientsAccepted() != accepted) sent_ = false;
    // Not yet sent (no client, or the last one dropped): send this cycle's
    // packet to whoever connects. Sent: read on for its answer (in slices,
    // to notice a new connection), never a new packet (LolaServer::exchange
    // says why).
    const Exchange e = sent_ ? server_.awaitAnswer(std::min(left, std::chrono::milliseconds(50)))
                             : server_.exchange(packet_, left);
    if (!sent_ && e.status != Exchange::Status::NoClient) sent_ = true;
    take(e);
  }
  return true;
}

void LolaBody::take(const Exchange& e) {
  switch (e.status) {
    case Exchange::Status::Answered:
      pending_ = e.command;
      answered_ = true;
      break;
    case Exchange::Status::NoClient:
    case Exchange::Status::Timeout:
      break;
    case Exchange::Status::Disconnected:
    case Exchange::Status::ProtocolError:
    case Exchange::Status::Stalled:
      std::fprintf(stderr, "robot %s: LoLA client on %s %s at tick %lld%s%s; waiting for it to connect again\n",
                   tag_.c_str(), server_.path().c_str(), toString(e.status), static_cast<long long>(tick_),
                   e.error.empty() ? "" : ": ", e.error.c_str());
      sent_ = false;  // the next client gets this cycle's packet
      break;
  }
}

al::ActuatorCommand LolaBody::readActuators() {
  if (answered_) {
    if (pending_.position) position_ = *pending_.position;
    if (pending_.stiffness) stiffness_ = *pending_.stiffness;
    answered_ = false;
    ++answers_;
  } else if (sync_ == SyncMode::FreeRunning && tick_ > 0) {
    ++skipped_;  // this tick's answer did not come in time: the last command stays
  }
  al::ActuatorCommand out;
  for (int j = 0; j < al::kNumJoints; ++j) {
    const int l = lolaJointOf(j);
    out.joints.angles[j] = position_[l];
    out.joints.stiffnesses[j] = stiffness_[l];
  }
  return out;
}

// LoLA has no way to tell a program the robot is going away: its socket is
// closed (the program's next read ends). A builtin program's Perception is
// woken through the extension object.
void LolaBody::shutdown() {
  objects_->shutdown();
  server_.dropClient();
}

}  // namespace simswift::lola
