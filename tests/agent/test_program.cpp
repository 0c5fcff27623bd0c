// The robot program: postures, the scripted Motion step and the threads.
#include <dirent.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <set>
#include <thread>

#include "common/libagent/SharedNames.hpp"
#include "agent/program/ScriptedMotion.hpp"
#include "agent/program/Postures.hpp"
#include "agent/program/RobotProgram.hpp"

namespace al = common::libagent;
namespace ap = agent::program;
namespace J = al::Joints;

TEST(Postures, StandAndCrouchKeepTheTorsoUprightOverFlatFeet) {
  for (ap::Posture p : {ap::Posture::Stand, ap::Posture::Crouch}) {
    const ap::JointArray a = ap::postureAngles(p);
    // Hip, knee and ankle pitch summing to 0 keeps foot and torso parallel.
    EXPECT_NEAR(a[J::LHipPitch] + a[J::LKneePitch] + a[J::LAnklePitch], 0.0, 1e-6);
    EXPECT_NEAR(a[J::RHipPitch] + a[J::RKneePitch] + a[J::RAnklePitch], 0.0, 1e-6);
    EXPECT_GT(a[J::LKneePitch], 0.5f);
    EXPECT_EQ(ap::postureStiffness(p), 1.0f);
  }
  EXPECT_EQ(ap::postureStiffness(ap::Posture::Limp), 0.0f);
  EXPECT_EQ(ap::parsePosture("crouch"), ap::Posture::Crouch);
  EXPECT_FALSE(ap::parsePosture("sit"));
  EXPECT_EQ(ap::jointIndex("RHand"), J::RHand);
  EXPECT_EQ(ap::jointIndex("RHipYawPitch"), -1);  // not a libagent slot
}

TEST(ScriptedMotion, MovesAJointAtItsTimeAndRampsOverDuration) {
  ap::ScriptStep step;
  step.t_s = 0.5;
  step.joint = J::HeadYaw;
  step.angle = 1.0f;
  step.duration_s = 0.2;
  ap::ScriptedMotion m(ap::Posture::Stand, {step});
  al::SensorValues s{};
  al::JointValues out{};
  m.tick(s, 490000, out);
  EXPECT_EQ(out.angles[J::HeadYaw], 0.0f);
  EXPECT_EQ(out.stiffnesses[J::HeadYaw], 1.0f);
  m.tick(s, 600000, out);  // half way through the ramp
  EXPECT_NEAR(out.angles[J::HeadYaw], 0.5f, 1e-4);
  m.tick(s, 800000, out);
  EXPECT_NEAR(out.angles[J::HeadYaw], 1.0f, 1e-6);
  // Other joints keep the posture.
  EXPECT_EQ(out.angles[J::LKneePitch], ap::postureAngles(ap::Posture::Stand)[J::LKneePitch]);
}

TEST(ScriptedMotion, PostureStepSwitchesTheWholeBody) {
  ap::ScriptStep step;
  step.t_s = 1.0;
  step.posture = ap::Posture::Limp;
  ap::ScriptedMotion m(ap::Posture::Stand, {step});
  al::SensorValues s{};
  al::JointValues out{};
  m.tick(s, 1000000, out);
  for (float st : out.stiffnesses) EXPECT_EQ(st, 0.0f);
}

namespace {
std::set<std::string> threadNames() {
  std::set<std::string> names;
  DIR* d = opendir("/proc/self/task");
  if (!d) return names;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    std::ifstream f(std::string("/proc/self/task/") + e->d_name + "/comm");
    std::string n;
    std::getline(f, n);
    names.insert(n);
  }
  closedir(d);
  return names;
}
}  // namespace

// The program's Motion thread answers each tick with a command; Perception
// answers each frame; both threads are named after the robot.
TEST(RobotProgram, RunsMotionAndPerceptionInLockStep) {
  std::unique_ptr<al::AgentData> block(new al::AgentData());
  std::unique_ptr<al::SimExtension> ext(new al::SimExtension());
  sem_t tick;
  sem_init(&tick, 0, 0);
  sem_init(&ext->answered, 1, 0);
  sem_init(&ext->camera.frame_ready, 1, 0);
  sem_init(&ext->camera.perception_done, 1, 0);
  ext->magic = al::kExtensionMagic;
  ext->version = al::kExtensionVersion;

  {
    ap::RobotProgram program(al::AgentConnection(block.get(), &tick, ext.get()), 1, 2,
                             std::make_unique<ap::PoseGenerator>(ap::Posture::Crouch));
    program.start();
    EXPECT_EQ(ext->client_pid.load(), 1);
    EXPECT_EQ(ext->camera.consumer.load(), 1);
    for (int k = 1; k <= 5; ++k) {
      // The body side: sensors, park the actuators, post, wait for the answer.
      ext->slot_time_us[0] = k * 10000;
      al::storeIndex(block->actuators_latest, al::kActuatorsParked);
      sem_post(&tick);
      timespec deadline{};
      clock_gettime(CLOCK_REALTIME, &deadline);
      deadline.tv_sec += 5;
      ASSERT_EQ(sem_timedwait(&ext->answered, &deadline), 0) << "tick " << k;
      EXPECT_TRUE(al::validSlot(al::loadIndex(block->actuators_latest))) << "tick " << k;
    }
    sem_post(&ext->camera.frame_ready);
    timespec deadline{};
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_sec += 5;
    ASSERT_EQ(sem_timedwait(&ext->camera.perception_done, &deadline), 0);

    const std::set<std::string> names = threadNames();
    EXPECT_TRUE(names.count("t1p2-motion")) << "thread names not set";
    EXPECT_TRUE(names.count("t1p2-percept"));

    const int slot = al::loadIndex(block->actuators_latest);
    EXPECT_EQ(block->joints[slot].angles[J::LKneePitch], ap::postureAngles(ap::Posture::Crouch)[J::LKneePitch]);

    ext->shutdown = 1;
    ext->camera.shutdown = 1;
    sem_post(&tick);
    sem_post(&ext->camera.frame_ready);
    program.join();
    // Counted after each answer: read once the threads have ended.
    EXPECT_EQ(program.motionTicks(), 5);
    EXPECT_EQ(program.perceptionFrames(), 1);
  }
  sem_destroy(&tick);
  sem_destroy(&ext->answered);
  sem_destroy(&ext->camera.frame_ready);
  sem_destroy(&ext->camera.perception_done);
}
