// The public API (include/simswift/Simulation.hpp) as a team's test uses
// it: only public headers, linked against libsimswift.so. Physics facts,
// the same hash for a controller and an external program sending the same
// commands, and errors that carry file, line and key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "simswift/Simulation.hpp"

namespace {

const std::string kBin = SIMSWIFT_BINARY_DIR;

// NAO V5 (H25) mass: 5.305 kg (Aldebaran's NAO V5 datasheet); the FSRs
// report kg, so a standing robot's eight sum to it.
constexpr double kNaoMassKg = 5.305;

double fsrSum(const simswift::SensorValues& s) {
  double sum = 0;
  for (int f = simswift::api::LFsrFrontLeft; f <= simswift::api::LFsrRearRight; ++f) sum += s.sensors[f];
  for (int f = simswift::api::RFsrFrontLeft; f <= simswift::api::RFsrRearRight; ++f) sum += s.sensors[f];
  return sum;
}

// The libagent test client's Motion (tests/libagent_client, default mode):
// hold the first tick's angles at stiffness 1, then turn the head 0.5 rad
// over ticks 50..100 and bend the knees over 100..200, back over 250..350.
struct ClientMotion {
  long k = 0;
  simswift::JointValues hold{};
  static float ramp(long k, long t0, long t1) {
    if (k <= t0) return 0.0f;
    if (k >= t1) return 1.0f;
    return static_cast<float>(k - t0) / static_cast<float>(t1 - t0);
  }
  void operator()(const simswift::SensorValues& s, simswift::JointValues& cmd) {
    using namespace simswift::api;
    if (++k == 1) {
      hold = s.joints;
      for (float& st : hold.stiffnesses) st = 1.0f;
    }
    cmd = hold;
    cmd.angles[HeadYaw] = hold.angles[HeadYaw] + 0.5f * ramp(k, 50, 100);
    const float d = 0.2f * (ramp(k, 100, 200) - ramp(k, 250, 350));
    for (int hip : {LHipPitch, RHipPitch}) cmd.angles[hip] = hold.angles[hip] - d;
    for (int knee : {LKneePitch, RKneePitch}) cmd.angles[knee] = hold.angles[knee] + 2.0f * d;
    for (int ankle : {LAnklePitch, RAnklePitch}) cmd.angles[ankle] = hold.angles[ankle] - d;
  }
};

std::string oneRobot(const std::string& program) {
  return "duration: 4\nseed: 9\nnoise: on\nprogram_logs: " + kBin +
         "/api_test_logs\nrobots:\n  - {team: 86, player: 1, x: 0.0, y: 1.0" + program + "}\n";
}

}  // namespace

TEST(Simulation, AStandingRobotsFsrsSumToItsMass) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(oneRobot(""), "stand.yaml", SIMSWIFT_SOURCE_DIR);
  EXPECT_EQ(sim.numRobots(), 1);
  sim.run(1.0);
  EXPECT_EQ(sim.ticks(), 100);
  EXPECT_NEAR(sim.time(), 1.0, 1e-9);
  double mean = 0;
  for (int k = 0; k < 50; ++k) {
    sim.step();
    mean += fsrSum(sim.robot(0).sensors()) / 50;
  }
  EXPECT_NEAR(mean, kNaoMassKg, 0.05 * kNaoMassKg);
  EXPECT_FALSE(sim.robot(0).fallen());
  EXPECT_NEAR(sim.robot(0).pose().y, 1.0, 0.02);
  EXPECT_GT(sim.robot(0).pose().z, 0.25);  // torso origin of a standing NAO, m
  ASSERT_TRUE(sim.ball().present);
  EXPECT_NEAR(sim.ball().x, 0.0, 1e-6);  // the centre spot
}

// The controller runs on the simulator's thread through the same libagent
// block and tick stage as an external program's Motion: the same commands
// (the test client's) give the same state hash.
TEST(Simulation, AControllerAndAnExternalProgramSendingTheSameCommandsGiveTheSameHash) {
  simswift::Simulation a = simswift::Simulation::fromYaml(oneRobot(""), "a.yaml", SIMSWIFT_SOURCE_DIR);
  a.robot(0).setController(ClientMotion{});
  a.run(4.0);
  simswift::Simulation b = simswift::Simulation::fromYaml(
      oneRobot(", program: {command: [" + kBin +
               "/libagent2017-client, --team, \"{team}\", --player, \"{player}\", --ticks, 400]}"),
      "b.yaml", SIMSWIFT_SOURCE_DIR);
  b.run(4.0);
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_NE(a.stateHash(), 0u);
  // The commands acted: the head turned.
  EXPECT_NEAR(a.robot(0).sensors().joints.angles[simswift::api::HeadYaw], 0.5, 0.05);
}

// A libagent controller gets what an external program gets in the block
// (docs/libagent.md): `start: limp` sits the body limp until the controller
// sends STIFFEN (tick 100); `standing` is then read once (tick 101) and the
// command holds; a chest click reaches the buttons once (bit 0); a stiff
// start shows `standing` on the first tick only.
TEST(Simulation, ALibagentControllerSeesStandingAndButtonsAndStiffensALimpStart) {
  using namespace simswift::api;
  simswift::Simulation sim = simswift::Simulation::fromYaml(
      oneRobot(", libagent: {start: limp}, actions: [{t: 0.5, click: chest}]"), "limp.yaml", SIMSWIFT_SOURCE_DIR);
  std::vector<long> standing_at, click_at;
  std::vector<float> stiffness_read;
  long k = 0;
  sim.robot(0).setController([&](const simswift::SensorValues& s, simswift::JointValues& j, simswift::Libagent& l) {
    ++k;
    if (l.standing) standing_at.push_back(k);
    if (l.buttons != 0) click_at.push_back(k * 100 + l.buttons);
    if (k < 100) stiffness_read.push_back(s.joints.stiffnesses[LKneePitch]);
    for (float& st : j.stiffnesses) st = 1.0f;
    for (float& a : j.angles) a = 0.0f;
    for (int hip : {LHipPitch, RHipPitch}) j.angles[hip] = -0.4f;
    for (int knee : {LKneePitch, RKneePitch}) j.angles[knee] = 0.8f;
    for (int ankle : {LAnklePitch, RAnklePitch}) j.angles[ankle] = -0.4f;
    l.stiffen = k == 100;
  });
  sim.step();
  const double z0 = sim.robot(0).pose().z;
  sim.run(0.98);  // to tick 99
  const double z_limp = sim.robot(0).pose().z;
  sim.run(2.0);
  EXPECT_LT(z_limp, z0 - 0.03);  // limp: the body sags although the controller commands a stiff stand
  for (float st : stiffness_read) ASSERT_EQ(st, 0.0f);
  EXPECT_EQ(standing_at, std::vector<long>({101}));
  // Pressed 0.5-0.6 s, out after more than 18 cycles up: one single click.
  ASSERT_EQ(click_at.size(), 1u);
  EXPECT_EQ(click_at[0] % 100, 1);
  EXPECT_NEAR(click_at[0] / 100, 80, 2);
  EXPECT_NEAR(sim.robot(0).sensors().joints.angles[LKneePitch], 0.8, 0.1);  // stiffened: the stand holds

  simswift::Simulation stiff = simswift::Simulation::fromYaml(oneRobot(""), "stiff.yaml", SIMSWIFT_SOURCE_DIR);
  std::vector<long> stiff_standing;
  long n = 0;
  stiff.robot(0).setController([&](const simswift::SensorValues& s, simswift::JointValues& j, simswift::Libagent& l) {
    ++n;
    if (l.standing) stiff_standing.push_back(n);
    j = s.joints;
    for (float& st : j.stiffnesses) st = 1.0f;
  });
  stiff.run(0.5);
  EXPECT_EQ(stiff_standing, std::vector<long>({1}));
}

TEST(Simulation, SetJointsHoldsACommandAndPushesAndTeleportsAct) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(oneRobot(""), "j.yaml", SIMSWIFT_SOURCE_DIR);
  simswift::JointValues j{};
  for (float& st : j.stiffnesses) st = 1.0f;
  for (int hip : {simswift::api::LHipPitch, simswift::api::RHipPitch}) j.angles[hip] = -0.4f;
  for (int knee : {simswift::api::LKneePitch, simswift::api::RKneePitch}) j.angles[knee] = 0.8f;
  for (int ankle : {simswift::api::LAnklePitch, simswift::api::RAnklePitch}) j.angles[ankle] = -0.4f;
  sim.robot(0).setJoints(j);
  sim.run(1.0);
  EXPECT_NEAR(sim.robot(0).sensors().joints.angles[simswift::api::LKneePitch], 0.8, 0.05);
  j.angles[simswift::api::HeadYaw] = -0.6f;  // after start: the held command changes
  sim.robot(0).setJoints(j);
  sim.run(1.0);
  EXPECT_NEAR(sim.robot(0).sensors().joints.angles[simswift::api::HeadYaw], -0.6, 0.05);
  sim.robot(0).push(6.0, 0.0);  // N*s: well above the ~3.5 N*s that topples a standing NAO
  sim.run(3.0);
  EXPECT_TRUE(sim.robot(0).fallen());
  EXPECT_EQ(sim.robot(0).falls(), 1);
  sim.robot(0).teleport(-2.0, 0.5, 1.0);
  sim.step();
  EXPECT_NEAR(sim.robot(0).pose().x, -2.0, 0.05);
  EXPECT_NEAR(sim.robot(0).pose().theta, 1.0, 0.05);
  EXPECT_THROW(sim.robot(0).setController([](const simswift::SensorValues&, simswift::JointValues&) {}),
               std::logic_error);
  EXPECT_THROW(sim.robot(1), std::out_of_range);
}

TEST(Simulation, BadScenariosThrowWithFileLineAndKey) {
  try {
    simswift::Simulation::fromYaml("duration: 4\nrobots:\n  - {team: 300, player: 1}\n", "bad.yaml");
    FAIL() << "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, "bad.yaml");
    EXPECT_EQ(e.line, 3);
    EXPECT_EQ(e.key, "robots[0].team");
  }
  try {
    simswift::Simulation::fromScenario("/no/such/scenario.yaml");
    FAIL() << "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/scenario.yaml"), std::string::npos) << e.what();
  }
}

// The error's file, line and key are those its throw site gave (issue 32;
// they were read back from the message before): a syntax error has a line
// and no key (the text's "YAML syntax error: ..." is no key path), a file
// name with ": 9: " in it is kept whole, and a URDF's error names the URDF.
TEST(Simulation, TheErrorsFileLineAndKeyAreTheThrowSitesOwn) {
  try {
    simswift::Simulation::fromYaml("duration: 4\nrobots: [{team: 3, player: 1}\n", "syntax.yaml");
    FAIL() << "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, "syntax.yaml") << e.what();
    EXPECT_EQ(e.line, 3) << e.what();  // yaml-cpp's mark: the end, the list still open
    EXPECT_EQ(e.key, "") << e.what();
  }
  try {
    simswift::Simulation::fromYaml("duration: 4\nrobots:\n  - {team: 300, player: 1}\n", "runs:9: a: b.yaml");
    FAIL() << "accepted";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, "runs:9: a: b.yaml") << e.what();
    EXPECT_EQ(e.line, 3) << e.what();
    EXPECT_EQ(e.key, "robots[0].team") << e.what();
  }
  // A URDF whose second line is a link without an inertial.
  const std::string urdf = ::testing::TempDir() + "simswift_api_bad_model.urdf";
  {
    std::FILE* f = std::fopen(urdf.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("<robot name=\"bad\">\n  <link name=\"torso\"/>\n</robot>\n", f);
    std::fclose(f);
  }
  simswift::Simulation sim = simswift::Simulation::fromYaml(
      "duration: 1\nmodel: " + urdf + "\nrobots:\n  - {team: 86, player: 1, x: 0.0, y: 1.0}\n", "urdf.yaml");
  try {
    sim.step();
    FAIL() << "started";
  } catch (const simswift::api::ConfigError& e) {
    EXPECT_EQ(e.file, urdf) << e.what();
    EXPECT_EQ(e.line, 2) << e.what();
    EXPECT_EQ(e.key, "") << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(urdf + ":2: ", 0), 0u) << e.what();
  }
  std::remove(urdf.c_str());
}

// Every call is valid before the first step: queries answer from the
// scenario (and start nothing, so a controller can still be set after
// them); what only a tick produces (the sensors) throws std::logic_error
// naming the call. Issue 34: fallen(), falls() and sensors() crashed here.
TEST(Simulation, CallsBeforeTheFirstStepAnswerFromTheScenarioOrThrowAClearError) {
  simswift::Simulation sim = simswift::Simulation::fromYaml(
      "duration: 4\nseed: 9\nball: {x: 1.5, y: -0.5}\nrobots:\n  - {team: 86, player: 1, x: -1.0, y: 1.0, theta: 0.5}\n",
      "before.yaml", SIMSWIFT_SOURCE_DIR);
  EXPECT_FALSE(sim.robot(0).fallen());  // every scenario posture starts upright
  EXPECT_EQ(sim.robot(0).falls(), 0);
  try {
    sim.robot(0).sensors();
    ADD_FAILURE() << "sensors() before the first step answered";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("robot 0: sensors() before the first step"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(sim.robot(0).pose().x, -1.0);
  EXPECT_EQ(sim.robot(0).pose().theta, 0.5);
  const simswift::BallState placed = sim.ball();
  EXPECT_TRUE(placed.present);
  EXPECT_EQ(placed.x, 1.5);
  EXPECT_EQ(placed.y, -0.5);
  EXPECT_EQ(placed.vx, 0.0);
  EXPECT_EQ(sim.stateHash(), 0u);  // no world yet (documented)
  EXPECT_EQ(sim.ticks(), 0);
  EXPECT_EQ(sim.time(), 0.0);
  // Nothing above started the simulation.
  EXPECT_NO_THROW(sim.robot(0).setController([](const simswift::SensorValues&, simswift::JointValues&) {}));
  sim.step();
  EXPECT_EQ(sim.ticks(), 1);
  // The ball as the scenario placed it is where the world put it (z: its
  // radius, 0.05 m on the SPL 2017 field; 1 mm: one tick of settling).
  EXPECT_NEAR(sim.ball().x, placed.x, 1e-3);
  EXPECT_NEAR(sim.ball().z, placed.z, 1e-3);
  EXPECT_NEAR(placed.z, 0.05, 1e-9);
  EXPECT_NO_THROW(sim.robot(0).sensors());  // read at the tick
  // `ball: none`: no ball before and after.
  simswift::Simulation none = simswift::Simulation::fromYaml(
      "duration: 1\nball: none\nrobots:\n  - {team: 86, player: 1, x: 0.0, y: 1.0}\n", "none.yaml",
      SIMSWIFT_SOURCE_DIR);
  EXPECT_FALSE(none.ball().present);
}

// A first step that fails (a missing model) fails the same way on every
// later call, and the calls that start the simulation (placeBall, push,
// teleport) throw the API's ConfigError with file, line and key. Issue 34:
// the second step said "setThreading: the runner has already started", and
// the others threw the simulator's internal error type.
TEST(Simulation, AFailedStartIsReportedAgainAndAsTheApisConfigError) {
  auto bad = [] {
    return simswift::Simulation::fromYaml(
        "duration: 1\nmodel: models/no_such_robot.urdf\nrobots:\n  - {team: 86, player: 1, x: 0.0, y: 1.0}\n",
        "model.yaml", SIMSWIFT_SOURCE_DIR);
  };
  auto expectModelError = [](const std::function<void()>& call, const char* what) {
    try {
      call();
      ADD_FAILURE() << what << ": no error";
    } catch (const simswift::api::ConfigError& e) {
      EXPECT_EQ(e.file, "model.yaml") << what;
      EXPECT_EQ(e.line, 2) << what;
      EXPECT_EQ(e.key, "model") << what;
      EXPECT_NE(std::string(e.what()).find("no_such_robot.urdf' not found"), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": not the API's ConfigError: " << e.what();
    }
  };
  simswift::Simulation sim = bad();
  expectModelError([&] { sim.step(); }, "first step");
  expectModelError([&] { sim.step(); }, "second step");
  expectModelError([&] { sim.run(1.0); }, "run after a failed step");
  simswift::Simulation a = bad();
  expectModelError([&] { a.placeBall(1.0, 0.0); }, "placeBall");
  simswift::Simulation b = bad();
  expectModelError([&] { b.robot(0).push(1.0, 0.0); }, "push");
  simswift::Simulation c = bad();
  expectModelError([&] { c.robot(0).teleport(1.0, 0.0, 0.0); }, "teleport");
}
