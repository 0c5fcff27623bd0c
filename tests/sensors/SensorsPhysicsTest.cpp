// Sensors read from the ODE world: a standing robot (FSRs carry its weight,
// the accelerometer reads gravity with the NAO's sign, the gyro is still),
// robots falling forward, backward and sideways and lying there (AngleY /
// AngleX, the gyro's and the accelerometer's V5 signs), a robot turned both
// ways (GyroscopeZ's V5 sign), sonar echoes from a goal post and from
// nothing, determinism of the noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "common/libagent/Inertial.hpp"
#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/runner/FallDetector.hpp"
#include "sim/sensors/SensorSuite.hpp"
#include "sim/world/World.hpp"

using namespace simswift;
using namespace simswift::sensors;
namespace S = common::libagent::Sensors;
namespace in = common::libagent::inertial;

namespace {

std::shared_ptr<const RobotModel> nao() {
  static auto model =
      std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  return model;
}

// The robot program's standing posture (agent/program/Postures.hpp), model joint order.
std::vector<double> standingPosture(const RobotModel& m) {
  return simswift::NaoBinding(m).posture(agent::program::postureAngles(agent::program::Posture::Stand));
}

int addRobot(World& w, double x, double y, double theta, float stiffness) {
  const auto q = standingPosture(*nao());
  const int i = w.addRobot(nao(), x, y, theta, q);
  w.robot(i).holdPosture(q, stiffness);
  return i;
}

double torsoZ(const World& w, int i) {
  return w.robot(i).linkPose(w.robot(i).model().rootLink()).translation().z();
}

float fsrSum(const SensorReading& r) {
  float s = 0;
  for (int k = S::LFoot_FSR_FrontLeft; k <= S::LFoot_FSR_RearRight; ++k) s += r.sensors[k];
  for (int k = S::RFoot_FSR_FrontLeft; k <= S::RFoot_FSR_RearRight; ++k) s += r.sensors[k];
  return s;
}

}  // namespace

// 60 s of standing; it runs in about 1.5 s of wall time.
// Contact and servo chatter in the physics makes single 10 ms samples jitter
// (accelerometer by up to ~1.6 m/s^2, gyro by up to ~0.2 rad/s, FSR sum by a
// few N), as a real IMU's raw samples do; the steady-state figures are
// checked on 100 ms means, single samples against looser bounds.
TEST(SensorsPhysics, StandingRobotFeelsItsWeightAndGravity) {
  World w(FieldConfig::spl2017());
  w.placeBall(-3, 2);
  const int i = addRobot(w, 0, 0, 0.4, 1.0f);
  SensorSuite suite(w, i, SensorConfig{});
  // 1 s to settle into the contact layer: placed in its posture, the robot
  // rocks for about 0.8 s (100 ms gyro means up to 0.05 rad/s) before it
  // stands still; the checks below are for standing, not for landing.
  for (int k = 0; k < 100; ++k) {
    w.step();
    suite.update(w);
  }
  const double weight = nao()->totalMass() * w.config().gravity;
  const double z0 = torsoZ(w, i);
  double worst_fsr = 0, worst_accz = 0, worst_gyro = 0, worst_dz = 0, worst_angle = 0;
  double sample_fsr = 0, sample_accz = 0, sample_gyro = 0;
  double sum_accz = 0;
  const int ticks = 6000, window = 10;
  double win_fsr = 0, win_accz = 0;
  Eigen::Vector3d win_gyro = Eigen::Vector3d::Zero();
  for (int k = 0; k < ticks; ++k) {
    w.step();
    suite.update(w);
    const SensorReading& r = suite.reading();
    const double accz = r.sensors[S::InertialSensor_AccelerometerZ];
    const Eigen::Vector3d g(r.sensors[S::InertialSensor_GyroscopeX], r.sensors[S::InertialSensor_GyroscopeY],
                            r.sensors[S::InertialSensor_GyroscopeZ]);
    sample_fsr = std::max(sample_fsr, std::abs(fsrSum(r) - weight) / weight);
    sample_accz = std::max(sample_accz, std::abs(accz + 9.81));
    sample_gyro = std::max(sample_gyro, g.norm());
    win_fsr += fsrSum(r) / window;
    win_accz += accz / window;
    win_gyro += g / window;
    if ((k + 1) % window == 0) {
      worst_fsr = std::max(worst_fsr, std::abs(win_fsr - weight) / weight);
      worst_accz = std::max(worst_accz, std::abs(win_accz + 9.81));
      worst_gyro = std::max(worst_gyro, win_gyro.norm());
      win_fsr = win_accz = 0;
      win_gyro.setZero();
    }
    worst_dz = std::max(worst_dz, std::abs(torsoZ(w, i) - z0));
    worst_angle = std::max({worst_angle, std::abs(double(r.sensors[S::InertialSensor_AngleX])),
                            std::abs(double(r.sensors[S::InertialSensor_AngleY]))});
    sum_accz += accz;
    // The raw slots carry the same sample in counts; GyrRef is unused.
    ASSERT_NEAR(r.sensors[S::InertialSensor_AccZ], accz * in::kAccCountsPerMetrePerSecondSquared, 1e-3);
    ASSERT_NEAR(r.sensors[S::InertialSensor_GyrY],
                r.sensors[S::InertialSensor_GyroscopeY] * in::kGyrCountsPerRadPerSecond, 1e-3);
    ASSERT_EQ(r.sensors[S::InertialSensor_GyrRef], 0.0f);
  }
  const SensorReading& r = suite.reading();
  std::printf("standing 60 s: weight %.2f N; worst 100 ms mean: FSR error %.2f%%, |AccelerometerZ+9.81| %.3f, "
              "|gyro| %.4f rad/s; worst sample: FSR %.2f%%, AccelerometerZ %.3f, gyro %.4f; mean %.4f; "
              "worst |dz| %.2f mm, worst |angle| %.4f rad\n",
              weight, 100 * worst_fsr, worst_accz, worst_gyro, 100 * sample_fsr, sample_accz, sample_gyro,
              sum_accz / ticks, 1000 * worst_dz, worst_angle);
  EXPECT_LT(worst_fsr, 0.05);
  EXPECT_LT(worst_accz, 0.3);
  EXPECT_LT(worst_gyro, 0.05);
  EXPECT_NEAR(sum_accz / ticks, -9.81, 0.05);
  EXPECT_LT(sample_fsr, 0.15);
  EXPECT_LT(sample_accz, 3.0);
  EXPECT_LT(sample_gyro, 0.5);
  EXPECT_LT(worst_dz, 0.005);
  EXPECT_LT(worst_angle, 0.1);
  // Both feet carry load; each centre of pressure lies under its foot.
  for (int foot : {0, 1}) {
    const int first = foot == 0 ? S::LFoot_FSR_FrontLeft : S::RFoot_FSR_FrontLeft;
    float sum = 0;
    for (int k = 0; k < 4; ++k) sum += r.sensors[first + k];
    EXPECT_GT(sum, 0.25 * weight) << "foot " << foot;
    EXPECT_NEAR(r.sensors[first + 4], 0.02, 0.06) << "CoP x, foot " << foot;
    EXPECT_NEAR(r.sensors[first + 5], 0.0, 0.04) << "CoP y, foot " << foot;
  }
  // Joint readings: angles near the commanded stand, plausible temperatures and currents.
  const auto q = standingPosture(*nao());
  for (int s = 0; s < 25; ++s) {
    const int j = simswift::NaoBinding(*nao()).joint(s);
    const bool hand = nao()->joints()[j].name.find("Hand") != std::string::npos;
    if (!hand) {
      EXPECT_NEAR(r.joint_angles[s], q[j], 0.1) << nao()->joints()[j].name;
    }
    EXPECT_GE(r.joint_temperatures[s], 27.0f);
    EXPECT_LT(r.joint_temperatures[s], 30.0f);
    EXPECT_GE(r.joint_currents[s], 0.0f);
    EXPECT_LT(r.joint_currents[s], 5.0f);
  }
  // Encoder angles are whole counts.
  const double step = SensorConfig{}.encoder_step;
  const int knee = [] {
    for (int s = 0; s < 25; ++s)
      if (nao()->joints()[simswift::NaoBinding(*nao()).joint(s)].name == "LKneePitch") return s;
    return 0;
  }();
  const double counts = r.joint_angles[knee] / step;
  EXPECT_NEAR(counts, std::round(counts), 1e-3);
  // 61 s at -1.5 A from a full 2.25 Ah pack.
  EXPECT_NEAR(r.sensors[S::Battery_Charge], 1.0 - 1.5 * 61.0 / (2.25 * 3600), 1e-5);
  EXPECT_FLOAT_EQ(r.sensors[S::Battery_Current], -1.5f);
}

namespace {
// A robot given a push (m/s, world, at 0.4 m height, growing with height
// like a topple about the feet); returns (AngleX, AngleY), the torso height
// and the inertial slots after 3 s, and the fastest roll and pitch rates on
// the way down (GyroscopeX / GyroscopeY, rad/s, signed).
struct Fall {
  double angle_x, angle_y, torso_z;
  std::array<float, common::libagent::kNumSensors> lying;
  double peak_roll_rate = 0, peak_pitch_rate = 0;
  double worst_raw_gyr = 0;  // rad/s: |DEG2RAD(GyrX or GyrY) / 2.35 - GyroscopeX or Y| (rUNSWift's conversion)
};
Fall pushedFall(const Eigen::Vector3d& push, float stiffness) {
  World w(FieldConfig::spl2017());
  w.placeBall(-3, 2);
  const int i = addRobot(w, 0, 0, 0, stiffness);
  SensorConfig c;
  c.noise = false;
  SensorSuite suite(w, i, c);
  const RobotBody& body = w.robot(i);
  for (int l = 0; l < static_cast<int>(body.model().links().size()); ++l) {
    // Scale the push with height so the robot tips rather than slides.
    const double z = body.linkPose(l).translation().z();
    const Eigen::Vector3d v = push * (z / 0.4);
    dBodySetLinearVel(body.body(l), v.x(), v.y(), v.z());
  }
  suite.reset(w);
  Fall f{};
  for (int k = 0; k < 300; ++k) {
    w.step();
    suite.update(w);
    const auto& s = suite.reading().sensors;
    const double gx = s[S::InertialSensor_GyroscopeX], gy = s[S::InertialSensor_GyroscopeY];
    if (std::fabs(gx) > std::fabs(f.peak_roll_rate)) f.peak_roll_rate = gx;
    if (std::fabs(gy) > std::fabs(f.peak_pitch_rate)) f.peak_pitch_rate = gy;
    for (int axis = 0; axis < 2; ++axis) {
      const double raw = s[S::InertialSensor_GyrX + axis] * M_PI / 180.0 / 2.35;  // rUNSWift's FilteredTouch
      f.worst_raw_gyr = std::max(f.worst_raw_gyr, std::fabs(raw - s[S::InertialSensor_GyroscopeX + axis]));
    }
  }
  const auto& s = suite.reading().sensors;
  f.angle_x = s[S::InertialSensor_AngleX];
  f.angle_y = s[S::InertialSensor_AngleY];
  f.torso_z = torsoZ(w, i);
  std::copy(s.begin(), s.end(), f.lying.begin());
  return f;
}

// Lying still: the accelerometer reads gravity with the V5's signs, i.e.
// AccelerometerX = g sin AngleY, AccelerometerY = g sin AngleX (face down
// AccelerometerX ~ +g, on the back ~ -g, on the right side AccelerometerY ~
// +g) and the rest of g on Z (its sign tells whether the torso's z axis
// points up or down: AngleX / AngleY cannot), and the raw AccX/Y/Z are the
// same in counts (65 per g).
void expectLyingAccelerometer(const Fall& f) {
  const double g = 9.81;
  const double x = f.lying[S::InertialSensor_AccelerometerX], y = f.lying[S::InertialSensor_AccelerometerY],
               z = f.lying[S::InertialSensor_AccelerometerZ];
  std::printf("  lying: Accelerometer (%.2f, %.2f, %.2f) m/s^2, Acc (%.1f, %.1f, %.1f) counts; "
              "peak roll rate %.2f, pitch rate %.2f rad/s\n",
              x, y, z, f.lying[S::InertialSensor_AccX], f.lying[S::InertialSensor_AccY],
              f.lying[S::InertialSensor_AccZ], f.peak_roll_rate, f.peak_pitch_rate);
  EXPECT_NEAR(x, g * std::sin(f.angle_y), 1.0);
  EXPECT_NEAR(y, g * std::sin(f.angle_x), 1.0);
  const double sx = std::sin(f.angle_x), sy = std::sin(f.angle_y);
  EXPECT_NEAR(std::fabs(z), g * std::sqrt(std::max(0.0, 1 - sx * sx - sy * sy)), 1.0);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(f.lying[S::InertialSensor_AccX + k],
                f.lying[S::InertialSensor_AccelerometerX + k] * in::kAccCountsPerMetrePerSecondSquared, 1e-3);
  EXPECT_LT(f.worst_raw_gyr, 1e-4);
}
}  // namespace

TEST(SensorsPhysics, LimpRobotFallingForwardReadsPositiveAngleY) {
  const Fall f = pushedFall({0.6, 0, 0}, 0.0f);
  std::printf("forward fall: AngleX %.3f AngleY %.3f torso z %.3f m\n", f.angle_x, f.angle_y, f.torso_z);
  EXPECT_GT(f.angle_y, 0.5);
  EXPECT_LT(std::abs(f.angle_x), 0.5);
  EXPECT_LT(f.torso_z, runner::FallDetector::kFallHeight);  // collapsed within 3 s
  EXPECT_GT(f.peak_pitch_rate, 1.0);  // pitching forward: GyroscopeY > 0
  EXPECT_GT(f.lying[S::InertialSensor_AccelerometerX], 4.0);  // face down: toward +g
  expectLyingAccelerometer(f);
}

TEST(SensorsPhysics, LimpRobotFallingBackwardReadsNegativeAngleY) {
  const Fall f = pushedFall({-0.6, 0, 0}, 0.0f);
  std::printf("backward fall: AngleX %.3f AngleY %.3f torso z %.3f m\n", f.angle_x, f.angle_y, f.torso_z);
  EXPECT_LT(f.angle_y, -0.5);
  EXPECT_LT(f.torso_z, runner::FallDetector::kFallHeight);
  EXPECT_LT(f.peak_pitch_rate, -1.0);  // pitching backward: GyroscopeY < 0
  EXPECT_LT(f.lying[S::InertialSensor_AccelerometerX], -4.0);  // on the back: toward -g
  expectLyingAccelerometer(f);
}

// A limp NAO folds at the knees and sits back whichever way it is pushed,
// so the sideways falls use a stiff robot toppled as a whole.
TEST(SensorsPhysics, RobotFallingToItsRightReadsPositiveAngleX) {
  const Fall f = pushedFall({0, -1.0, 0}, 1.0f);
  std::printf("right fall: AngleX %.3f AngleY %.3f torso z %.3f m\n", f.angle_x, f.angle_y, f.torso_z);
  EXPECT_GT(f.angle_x, 1.0);
  EXPECT_LT(std::abs(f.angle_y), 0.5);
  EXPECT_LT(f.torso_z, runner::FallDetector::kFallHeight);
  EXPECT_GT(f.peak_roll_rate, 1.0);  // rolling to its right: GyroscopeX > 0
  EXPECT_GT(f.lying[S::InertialSensor_AccelerometerY], 4.0);  // on its right side: toward +g
  expectLyingAccelerometer(f);
}

TEST(SensorsPhysics, RobotFallingToItsLeftReadsNegativeAngleX) {
  const Fall f = pushedFall({0, 1.0, 0}, 1.0f);
  std::printf("left fall: AngleX %.3f AngleY %.3f torso z %.3f m\n", f.angle_x, f.angle_y, f.torso_z);
  EXPECT_LT(f.angle_x, -1.0);
  EXPECT_LT(std::abs(f.angle_y), 0.5);
  EXPECT_LT(f.torso_z, runner::FallDetector::kFallHeight);
  EXPECT_LT(f.peak_roll_rate, -1.0);
  EXPECT_LT(f.lying[S::InertialSensor_AccelerometerY], -4.0);
  expectLyingAccelerometer(f);
}

// A standing robot lifted 5 cm (so the soles' friction does not brake it)
// and spun about the vertical: the V5 reads an anti-clockwise turn as a
// NEGATIVE GyroscopeZ, a clockwise one as positive; rUNSWift's odometry turn
// per 10 ms frame, -0.01 * GyroscopeZ, has the turn's sign.
TEST(SensorsPhysics, RobotTurnedBothWaysReadsTheV5GyroscopeZ) {
  for (double rate : {1.0, -1.0}) {
    World w(FieldConfig::spl2017());
    w.placeBall(-3, 2);
    const int i = addRobot(w, 0, 0, 0.4, 1.0f);
    SensorConfig c;
    c.noise = false;
    SensorSuite suite(w, i, c);
    for (int k = 0; k < 50; ++k) {
      w.step();
      suite.update(w);
    }
    const RobotBody& body = w.robot(i);
    const Eigen::Vector3d centre = body.linkPose(body.model().rootLink()).translation();
    const Eigen::Vector3d omega(0, 0, rate);
    for (int l = 0; l < static_cast<int>(body.model().links().size()); ++l) {
      const dReal* p = dBodyGetPosition(body.body(l));
      const Eigen::Vector3d at(p[0], p[1], p[2] + 0.05);
      const Eigen::Vector3d v = omega.cross(at - centre);
      dBodySetPosition(body.body(l), at.x(), at.y(), at.z());
      dBodySetLinearVel(body.body(l), v.x(), v.y(), v.z());
      dBodySetAngularVel(body.body(l), 0, 0, rate);
    }
    suite.reset(w);
    double turned_by_odometry = 0;  // rad, rUNSWift's MotionOdometry sum (without its 0.95)
    for (int k = 0; k < 3; ++k) {
      w.step();
      suite.update(w);
      turned_by_odometry += -0.01 * suite.reading().sensors[S::InertialSensor_GyroscopeZ];
    }
    const auto& s = suite.reading().sensors;
    std::printf("turned at %+.1f rad/s: GyroscopeX/Y/Z (%.3f, %.3f, %.3f) rad/s, GyrX/Y (%.2f, %.2f), "
                "AccelerometerZ %.2f\n",
                rate, s[S::InertialSensor_GyroscopeX], s[S::InertialSensor_GyroscopeY],
                s[S::InertialSensor_GyroscopeZ], s[S::InertialSensor_GyrX], s[S::InertialSensor_GyrY],
                s[S::InertialSensor_AccelerometerZ]);
    EXPECT_NEAR(s[S::InertialSensor_GyroscopeZ], -rate, 0.05) << rate;
    EXPECT_NEAR(turned_by_odometry, 0.03 * rate, 0.002) << rate;
    EXPECT_NEAR(s[S::InertialSensor_GyroscopeX], 0.0, 0.05);
    EXPECT_NEAR(s[S::InertialSensor_GyroscopeY], 0.0, 0.05);
    EXPECT_NEAR(in::bodyRates(s.data()).z, rate, 0.05);  // the robot code's reader
    EXPECT_NEAR(s[S::InertialSensor_AccelerometerZ], 0.0, 1.0);  // lifted: falling freely
  }
}

namespace {
// Runs a standing robot for 0.3 s and returns its sonar.
std::array<float, 20> sonarAt(double x, double y, double theta, Eigen::Vector3d* left_origin) {
  World w(FieldConfig::spl2017());
  w.placeBall(-3, 2);
  const int i = addRobot(w, x, y, theta, 1.0f);
  SensorSuite suite(w, i, SensorConfig{});
  for (int k = 0; k < 30; ++k) {
    w.step();
    suite.update(w);
  }
  const RobotBody& b = w.robot(i);
  if (left_origin) *left_origin = b.linkPose(b.model().rootLink()) * leftSonarBeam(0, 0).origin;
  return suite.reading().sonar;
}
}  // namespace

TEST(SensorsPhysics, SonarSeesAGoalPostHalfAMetreAhead) {
  // The left post of the +x goal: a 0.1 m capsule at (4.5, 0.8). Robot
  // facing +x, chest 0.5 m from the post's surface.
  const FieldConfig f = FieldConfig::spl2017();
  const Eigen::Vector2d post(f.length / 2, f.goal.inner_width / 2 + f.goal.post_diameter / 2);
  Eigen::Vector3d origin;
  const auto sonar = sonarAt(post.x() - f.goal.post_diameter / 2 - 0.5 - 0.05, post.y(), 0.0, &origin);
  const double truth = (origin.head<2>() - post).norm() - f.goal.post_diameter / 2;
  std::printf("post: truth %.3f m, Left0 %.3f Right0 %.3f Left1 %.3f\n", truth, sonar[0], sonar[10], sonar[1]);
  EXPECT_NEAR(truth, 0.5, 0.03);
  EXPECT_NEAR(sonar[0], truth, 0.05);
  EXPECT_NEAR(sonar[10], truth, 0.05);
}

TEST(SensorsPhysics, SonarReadsNoEchoWithNothingAhead) {
  const auto sonar = sonarAt(0, 0, 0.0, nullptr);
  for (int k = 0; k < 20; ++k) EXPECT_EQ(sonar[k], common::libagent::kSonarNoEcho) << "echo " << k;
}

TEST(SensorsPhysics, SonarSeesAnotherRobotAhead) {
  World w(FieldConfig::spl2017());
  w.placeBall(-3, 2);
  const int me = addRobot(w, 0, 0, 0, 1.0f);
  addRobot(w, 0.55, 0, M_PI, 1.0f);  // facing us, torsos 0.55 m apart
  SensorSuite suite(w, me, SensorConfig{});
  for (int k = 0; k < 30; ++k) {
    w.step();
    suite.update(w);
  }
  const auto& s = suite.reading().sonar;
  std::printf("robot ahead: Left0 %.3f Right0 %.3f\n", s[0], s[10]);
  EXPECT_LT(s[0], 0.55f);
  EXPECT_GT(s[0], 0.3f);
  EXPECT_LT(s[10], 0.55f);
}

TEST(SensorsPhysics, ButtonsAndSonarModeAreEchoed) {
  World w(FieldConfig::spl2017());
  const int i = addRobot(w, 0, 0, 0, 1.0f);
  SensorSuite suite(w, i, SensorConfig{});
  suite.setButton(Button::Chest, true);
  suite.setButton(Button::HeadRear, true);
  suite.setSonarMode(68.0f);
  w.step();
  suite.update(w);
  const auto& s = suite.reading().sensors;
  EXPECT_EQ(s[S::ChestBoard_Button], 1.0f);
  EXPECT_EQ(s[S::Head_Touch_Rear], 1.0f);
  EXPECT_EQ(s[S::Head_Touch_Front], 0.0f);
  EXPECT_EQ(s[S::Head_Touch_Middle], 0.0f);
  EXPECT_EQ(s[S::US], 68.0f);
  // The libagent slot receives every value, the FSRs in the NAO's kg (N / g);
  // stiffnesses are left alone.
  common::libagent::SensorValues slot{};
  slot.joints.stiffnesses[3] = 0.7f;
  copyToAgent(suite.reading(), slot);
  for (int k = 0; k < common::libagent::kNumSensors; ++k) {
    const bool fsr = (k >= S::LFoot_FSR_FrontLeft && k <= S::LFoot_FSR_RearRight) ||
                     (k >= S::RFoot_FSR_FrontLeft && k <= S::RFoot_FSR_RearRight);
    if (fsr) EXPECT_FLOAT_EQ(slot.sensors[k], s[k] / 9.81f) << k;
    else EXPECT_EQ(slot.sensors[k], s[k]) << k;
  }
  for (int k = 0; k < common::libagent::kNumJoints; ++k) {
    EXPECT_EQ(slot.joints.angles[k], suite.reading().joint_angles[k]);
    EXPECT_EQ(slot.joints.currents[k], suite.reading().joint_currents[k]);
  }
  EXPECT_EQ(slot.sonar[19], suite.reading().sonar[19]);
  EXPECT_EQ(slot.joints.stiffnesses[3], 0.7f);

  suite.setButton(Button::Chest, false);
  w.step();
  suite.update(w);
  EXPECT_EQ(suite.reading().sensors[S::ChestBoard_Button], 0.0f);
}

TEST(SensorsPhysics, NoiseIsPerRobotDeterministicAndOptional) {
  // A noisy and a noiseless suite on the same robot see the same truth, so
  // their difference is the noise alone. Robot 0's noise must not change
  // when a second robot joins the world, and two runs agree bit for bit.
  auto run = [](bool second_robot) {
    World w(FieldConfig::spl2017());
    w.placeBall(-3, 2);
    const int i = addRobot(w, 0, 0, 0, 1.0f);
    if (second_robot) addRobot(w, -3, -2, 0, 1.0f);
    SensorConfig noisy, exact;
    exact.noise = false;
    SensorSuite a(w, i, noisy), b(w, i, exact);
    std::vector<double> noise, raw;
    for (int k = 0; k < 20; ++k) {
      w.step();
      a.update(w);
      b.update(w);
      // IMU slots: unclamped, so the difference is exactly bias + sigma * N(0,1).
      for (int s = S::InertialSensor_AccX; s <= S::InertialSensor_AccelerometerZ; ++s) {
        noise.push_back(double(a.reading().sensors[s]) - double(b.reading().sensors[s]));
        raw.push_back(a.reading().sensors[s]);
      }
    }
    return std::make_pair(noise, raw);
  };
  const auto one = run(false), again = run(false), two = run(true);
  EXPECT_EQ(one.second, again.second);  // bit-identical runs
  ASSERT_EQ(one.first.size(), two.first.size());
  double largest = 0;
  for (size_t k = 0; k < one.first.size(); ++k) {
    // Float rounding only (relative: the raw slots are in counts, up to ~65).
    EXPECT_NEAR(one.first[k], two.first[k], 1e-5 * std::max(1.0, std::fabs(one.second[k]))) << "sample " << k;
    largest = std::max(largest, std::abs(one.first[k]));
  }
  EXPECT_GT(largest, 0.005);  // the noisy suite is noisy
}

TEST(SensorsPhysics, BallRollingIntoTheToePressesThatBumper) {
  // Standing robot facing +x with its left foot at y = +0.05 m; a ball rolls
  // at its left toe's outer (left) half. The carpet never presses a bumper.
  World w(FieldConfig::spl2017());
  const int i = addRobot(w, 0, 0, 0, 1.0f);
  w.placeBall(0.35, 0.08);
  SensorSuite suite(w, i, SensorConfig{});
  int left_left = 0, others = 0;
  for (int k = 0; k < 100; ++k) {
    if (k == 10) w.setBallVelocity({-1.5, 0, 0});
    w.step();
    suite.update(w);
    const auto& s = suite.reading().sensors;
    if (k < 10) {
      ASSERT_EQ(s[S::LFoot_Bumper_Left] + s[S::LFoot_Bumper_Right] + s[S::RFoot_Bumper_Left] +
                    s[S::RFoot_Bumper_Right],
                0.0f)
          << "bumper pressed by the carpet";
    }
    left_left += s[S::LFoot_Bumper_Left] > 0;
    others += (s[S::LFoot_Bumper_Right] + s[S::RFoot_Bumper_Left] + s[S::RFoot_Bumper_Right]) > 0;
  }
  std::printf("bumper: LFoot left pressed %d ticks, others %d ticks\n", left_left, others);
  EXPECT_GE(left_left, 1);
  EXPECT_EQ(others, 0);
}
