// Scenario button presses reach the robot program's sensors through the
// libagent block, at the simulated times the scenario gives.
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

namespace al = common::libagent;
namespace ap = agent::program;
using simswift::runner::RunOptions;
using simswift::runner::Runner;
using simswift::runner::Scenario;

namespace {

// Stands, and records the simulated times (us) at which a button read pressed.
class RecordingMotion : public agent::framework::MotionGenerator {
 public:
  RecordingMotion(std::vector<int64_t>* chest, std::vector<int64_t>* head) : chest_(chest), head_(head) {}
  void tick(const al::SensorValues& s, int64_t t_us, al::JointValues& out) override {
    out = ap::postureCommand(ap::Posture::Stand);
    if (s.sensors[al::Sensors::ChestBoard_Button] > 0.5f) chest_->push_back(t_us);
    if (s.sensors[al::Sensors::Head_Touch_Middle] > 0.5f) head_->push_back(t_us);
  }

 private:
  std::vector<int64_t>* chest_;
  std::vector<int64_t>* head_;
};

}  // namespace

TEST(RunnerButtons, ScenarioPressesReachTheRobotAtTheirTimes) {
  const Scenario s = Scenario::parse(
      "duration: 1\nrobots:\n  - {team: 0, player: 1, x: -1.0,\n"
      "     buttons: [{t: 0.2, button: chest, duration: 0.05}, {t: 0.5, button: head_middle}]}\n",
      "test.yaml");
  std::vector<int64_t> chest, head;
  Runner r(s);
  r.programs().setMotionGenerator(0, std::make_unique<RecordingMotion>(&chest, &head));
  RunOptions o;
  o.progress = false;
  r.run(o);
  // Sensors of tick k carry time k * 10 ms; a press covers [t, t + duration).
  EXPECT_EQ(chest, (std::vector<int64_t>{200000, 210000, 220000, 230000, 240000}));
  ASSERT_EQ(head.size(), 10u);  // default duration 0.1 s
  EXPECT_EQ(head.front(), 500000);
  EXPECT_EQ(head.back(), 590000);
}

TEST(RunnerButtons, UnknownButtonIsAnErrorNamingTheKey) {
  try {
    Scenario::parse("duration: 1\nrobots:\n  - {team: 0, player: 1, buttons: [{t: 1, button: nose}]}\n",
                    "b.yaml");
    FAIL() << "expected an error";
  } catch (const simswift::ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("b.yaml:3"), std::string::npos) << m;
    EXPECT_NE(m.find("button"), std::string::npos) << m;
  }
}
