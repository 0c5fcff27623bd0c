#include "sim/sensors/SensorSuite.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/nao_model/NaoBinding.hpp"
#include "sim/sensors/JointEncoders.hpp"
#include "sim/world/World.hpp"

namespace simswift::sensors {

namespace S = la::Sensors;

void copyToAgent(const SensorReading& r, la::SensorValues& out) {
  std::copy(r.joint_angles.begin(), r.joint_angles.end(), out.joints.angles);
  std::copy(r.joint_temperatures.begin(), r.joint_temperatures.end(), out.joints.temperatures);
  std::copy(r.joint_currents.begin(), r.joint_currents.end(), out.joints.currents);
  std::copy(r.sensors.begin(), r.sensors.end(), out.sensors);
  // The FSRs in the NAO's unit: kg (N / g).
  for (int first : {S::LFoot_FSR_FrontLeft, S::RFoot_FSR_FrontLeft})
    for (int k = first; k < first + 4; ++k)
      out.sensors[k] = static_cast<float>(r.sensors[k] / la::kFsrNewtonsPerKilogram);
  std::copy(r.sonar.begin(), r.sonar.end(), out.sonar);
}

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The link moved by `joint_name` (the ankle frame for L/RAnkleRoll).
int childOf(const RobotModel& model, const std::string& joint_name) {
  const int j = model.jointIndex(joint_name);
  if (j < 0)
    throw std::runtime_error("SensorSuite: robot model has no joint '" + joint_name +
                             "' (the FSRs and bumpers hang from the ankle-roll link)");
  return model.joints()[j].child_link;
}

// True if `link` is `root` or hangs below it.
bool below(const RobotModel& model, int link, int root) {
  for (int l = link; l >= 0;) {
    if (l == root) return true;
    const int pj = model.links()[l].parent_joint;
    if (pj < 0) return false;
    l = model.joints()[pj].parent_link;
  }
  return false;
}

}  // namespace

SensorSuite::SensorSuite(const World& world, int robot, const SensorConfig& config)
    : robot_(robot),
      config_(config),
      gyro_noise_(config.seed, robot, StreamId::Gyroscope),
      accel_noise_(config.seed, robot, StreamId::Accelerometer),
      angle_noise_(config.seed, robot, StreamId::Angle),
      encoder_noise_(config.seed, robot, StreamId::JointEncoders),
      fsr_noise_{{NoiseStream(config.seed, robot, StreamId::LeftFsr),
                  NoiseStream(config.seed, robot, StreamId::RightFsr)}},
      sonar_noise_{{NoiseStream(config.seed, robot, StreamId::LeftSonar),
                    NoiseStream(config.seed, robot, StreamId::RightSonar)}},
      fsr_layout_{{FsrLayout::left(), FsrLayout::right()}},
      sonar_beam_{{leftSonarBeam(config.sonar_yaw, config.sonar_pitch),
                   rightSonarBeam(config.sonar_yaw, config.sonar_pitch)}},
      battery_(config.battery_start, config.battery_current, config.battery_capacity) {
  config_.validate();
  if (robot < 0 || robot >= world.numRobots())
    throw std::out_of_range("SensorSuite: robot index " + std::to_string(robot) + " not in the world (" +
                            std::to_string(world.numRobots()) + " robots)");
  const RobotModel& model = world.robot(robot).model();
  foot_link_[0] = childOf(model, "LAnkleRoll");
  foot_link_[1] = childOf(model, "RAnkleRoll");
  link_foot_.assign(model.links().size(), -1);
  for (int l = 0; l < static_cast<int>(model.links().size()); ++l) {
    if (below(model, l, foot_link_[0])) link_foot_[l] = 0;
    if (below(model, l, foot_link_[1])) link_foot_[l] = 1;
  }
  const NaoBinding nao(model);
  for (int i = 0; i < la::kNumJoints; ++i) {
    const int j = nao.joint(i);
    joint_of_slot_[i] = j;
    is_hand_[i] = endsWith(model.joints()[j].name, "Hand");
  }
  reading_.sonar.fill(la::kSonarNoEcho);
  reset(world);
}

void SensorSuite::reset(const World& world) {
  const RobotBody& body = world.robot(robot_);
  const int torso = body.model().rootLink();
  imu_.reset(body.linkPose(torso).linear(), body.linkLinearVelocity(torso, accelerometerPoint()));
  last_tick_ = world.tick();
}

void SensorSuite::update(const World& world) {
  // A gap in ticks (or the first call) means the velocity history is stale.
  if (world.tick() != last_tick_ + 1) reset(world);
  const double dt = world.tickSeconds();
  last_tick_ = world.tick();

  updateJoints(world, dt);
  updateImu(world, dt);
  updateFeet(world);
  if (world.tick() % config_.sonar_period_ticks == 0) updateSonar(world);

  auto& s = reading_.sensors;
  s[S::ChestBoard_Button] = buttons_[static_cast<int>(Button::Chest)] ? 1.0f : 0.0f;
  s[S::Head_Touch_Front] = buttons_[static_cast<int>(Button::HeadFront)] ? 1.0f : 0.0f;
  s[S::Head_Touch_Middle] = buttons_[static_cast<int>(Button::HeadMiddle)] ? 1.0f : 0.0f;
  s[S::Head_Touch_Rear] = buttons_[static_cast<int>(Button::HeadRear)] ? 1.0f : 0.0f;
  battery_.step(dt);
  s[S::Battery_Charge] = static_cast<float>(battery_.charge());
  s[S::Battery_Current] = static_cast<float>(battery_.current());
  s[S::US] = sonar_mode_;
}

void SensorSuite::updateJoints(const World& world, double /*dt*/) {
  const RobotBody& body = world.robot(robot_);
  const RobotModel& model = body.model();
  for (int i = 0; i < la::kNumJoints; ++i) {
    const int j = joint_of_slot_[i];
    const JointSpec& spec = model.joints()[j];
    const double measured = quantise(
        encoder_noise_.perturb(body.jointAngle(j), config_.encoder.sigma, config_.encoder.bias, config_.noise),
        config_.encoder_step);
    reading_.joint_angles[i] = static_cast<float>(encoderValue(measured, is_hand_[i], spec.lower, spec.upper));
    // The motor model's own figures (Servo.hpp): A and deg C.
    reading_.joint_temperatures[i] = static_cast<float>(body.jointTemperature(j));
    reading_.joint_currents[i] = static_cast<float>(body.jointCurrent(j));
  }
}

void SensorSuite::updateImu(const World& world, double dt) {
  const RobotBody& body = world.robot(robot_);
  const int torso = body.model().rootLink();
  const Eigen::Isometry3d pose = body.linkPose(torso);
  const ImuSample t = imu_.update(pose.linear(), body.linkAngularVelocity(torso),
                                  body.linkLinearVelocity(torso, accelerometerPoint()), dt,
                                  world.config().gravity);
  // Noise in the sensors' own axes, before the V5's signs and scales.
  const bool on = config_.noise;
  ImuSample m;
  for (int k = 0; k < 3; ++k) {
    m.gyro[k] = gyro_noise_.perturb(t.gyro[k], config_.gyro.sigma, config_.gyro.bias, on);
    m.specific_force[k] = accel_noise_.perturb(t.specific_force[k], config_.accel.sigma, config_.accel.bias, on);
  }
  m.angle_x = angle_noise_.perturb(t.angle_x, config_.angle.sigma, config_.angle.bias, on);
  m.angle_y = angle_noise_.perturb(t.angle_y, config_.angle.sigma, config_.angle.bias, on);
  writeV5InertialSlots(m, config_.gyr_raw_sign, config_.acc_raw_sign, reading_.sensors.data());
}

void SensorSuite::updateFeet(const World& world) {
  const RobotBody& body = world.robot(robot_);
  std::array<std::array<double, 4>, 2> forces{};
  std::array<BumperHit, 2> bumpers{};
  std::array<Eigen::Isometry3d, 2> foot_inv{
      {body.linkPose(foot_link_[0]).inverse(), body.linkPose(foot_link_[1]).inverse()}};
  for (const LinkContact& c : world.contacts()) {
    if (c.robot != robot_ || c.link < 0 || c.link >= static_cast<int>(link_foot_.size())) continue;
    const int foot = link_foot_[c.link];
    if (foot < 0) continue;
    const Eigen::Vector3d p = foot_inv[foot] * c.position;     // m, ankle frame
    const Eigen::Vector3d f = foot_inv[foot].linear() * c.force;  // N, ankle axes
    // The FSRs sit between sole plate and sole: only the push along the
    // foot's z axis loads them.
    distributeForce(fsr_layout_[foot], p.head<2>(), f.z(), forces[foot]);
    if (c.other != GeomTag::Ground && c.force.norm() >= config_.bumper_min_force) {
      const BumperHit h = bumperFor(p, foot == 0, config_.bumper_min_x);
      bumpers[foot].left |= h.left;
      bumpers[foot].right |= h.right;
    }
  }

  auto& s = reading_.sensors;
  const int first[2] = {S::LFoot_FSR_FrontLeft, S::RFoot_FSR_FrontLeft};
  const int cop[2] = {S::LFoot_FSR_CenterOfPressure_X, S::RFoot_FSR_CenterOfPressure_X};
  for (int foot = 0; foot < 2; ++foot) {
    std::array<double, 4>& fz = forces[foot];
    for (double& v : fz) v = fsr_noise_[foot].perturb(v, config_.fsr.sigma, config_.fsr.bias, config_.noise);
    saturate(fz, config_.fsr_max);
    for (int k = 0; k < 4; ++k) s[first[foot] + k] = static_cast<float>(fz[k]);
    const Eigen::Vector2d c = centreOfPressure(fsr_layout_[foot], fz, config_.fsr_unloaded);
    s[cop[foot]] = static_cast<float>(c.x());
    s[cop[foot] + 1] = static_cast<float>(c.y());
  }
  s[S::LFoot_Bumper_Left] = bumpers[0].left ? 1.0f : 0.0f;
  s[S::LFoot_Bumper_Right] = bumpers[0].right ? 1.0f : 0.0f;
  s[S::RFoot_Bumper_Left] = bumpers[1].left ? 1.0f : 0.0f;
  s[S::RFoot_Bumper_Right] = bumpers[1].right ? 1.0f : 0.0f;
}

void SensorSuite::updateSonar(const World& world) {
  const RobotBody& body = world.robot(robot_);
  const Eigen::Isometry3d torso = body.linkPose(body.model().rootLink());
  const RayFunction ray = [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d, double range) {
    return world.rayCast(o, d, range, robot_);
  };
  for (int side = 0; side < 2; ++side) {
    const std::vector<double> hits =
        castSonar(sonar_beam_[side], config_.sonar_cone, torso, config_.sonar_max_range, ray);
    std::array<float, 10> echoes = sonarEchoes(hits, config_.sonar_min_range, config_.sonar_max_range,
                                               config_.sonar_echo_separation, la::kSonarNoEcho);
    // Noise per echo (not per ray: the nearest of many noisy rays would be
    // biased short), kept inside the reported range.
    for (float& e : echoes) {
      if (e == la::kSonarNoEcho) continue;
      const double noisy = sonar_noise_[side].perturb(e, config_.sonar.sigma, config_.sonar.bias, config_.noise);
      e = static_cast<float>(std::clamp(noisy, config_.sonar_min_range, config_.sonar_max_range));
    }
    std::copy(echoes.begin(), echoes.end(), reading_.sonar.begin() + 10 * side);
  }
}

}  // namespace simswift::sensors
