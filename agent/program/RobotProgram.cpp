#include "agent/program/RobotProgram.hpp"

#include <pthread.h>

#include <cstdio>

#include "agent/libagent/SharedNames.hpp"

namespace agent::program {

using agent::libagent::JointValues;
using agent::libagent::SensorValues;

namespace {
void nameThisThread(const std::string& name) {
  // Linux limits thread names to 15 characters.
  pthread_setname_np(pthread_self(), name.substr(0, 15).c_str());
}
}  // namespace

RobotProgram::RobotProgram(agent::libagent::AgentConnection connection, int team, int player,
                           std::unique_ptr<MotionGenerator> motion, std::unique_ptr<PerceptionStep> perception)
    : conn_(std::move(connection)),
      tag_(agent::libagent::robotTag(team, player)),
      motion_(std::move(motion)),
      perception_(std::move(perception)) {}

RobotProgram::~RobotProgram() { join(); }

void RobotProgram::setMotion(std::unique_ptr<MotionGenerator> motion) {
  if (motion_thread_.joinable()) throw std::logic_error("RobotProgram::setMotion after start");
  motion_ = std::move(motion);
}

void RobotProgram::start() {
  const bool with_perception = conn_.hasCamera() && perception_ != nullptr;
  // Announce first: the simulator decides whether to send camera frames once
  // Motion has answered its first tick, which may happen as soon as the
  // thread exists.
  conn_.announce(with_perception);
  motion_thread_ = std::thread([this] { motionLoop(); });
  if (with_perception) {
    perception_->setImages(conn_.images());
    perception_thread_ = std::thread([this] { perceptionLoop(); });
  }
}

void RobotProgram::join() {
  if (motion_thread_.joinable()) motion_thread_.join();
  if (perception_thread_.joinable()) perception_thread_.join();
}

std::string RobotProgram::error() const {
  std::lock_guard<std::mutex> lock(error_mutex_);
  return error_;
}

void RobotProgram::fail(const std::string& thread, const std::exception& e) {
  std::lock_guard<std::mutex> lock(error_mutex_);
  if (error_.empty()) error_ = tag_ + "-" + thread + ": " + e.what();
  std::fprintf(stderr, "robot %s: %s thread stopped: %s\n", tag_.c_str(), thread.c_str(), e.what());
}

void RobotProgram::motionLoop() {
  nameThisThread(tag_ + "-motion");
  try {
    JointValues cmd{};
    bool first = true;
    while (conn_.waitTick()) {
      const SensorValues sensors = conn_.readSensors();
      const int64_t t = conn_.simTimeUs();
      if (first) {
        // Start from the measured angles, so a generator that only touches
        // some joints leaves the others where they are.
        for (int i = 0; i < agent::libagent::kNumJoints; ++i) {
          cmd.angles[i] = sensors.joints.angles[i];
          cmd.stiffnesses[i] = 1.0f;
        }
        first = false;
      }
      if (motion_) motion_->tick(sensors, t, cmd);
      conn_.writeActuators(cmd);
      motion_ticks_.fetch_add(1);
      if (after_tick_) after_tick_(sensors, t);
    }
  } catch (const std::exception& e) {
    // No acknowledgement follows: the simulator's watchdog reports this robot.
    fail("motion", e);
  }
}

void RobotProgram::perceptionLoop() {
  nameThisThread(tag_ + "-percept");
  try {
    while (conn_.waitFrame()) {
      perception_->step(conn_.frame());
      perception_frames_.fetch_add(1);
      conn_.perceptionDone();
    }
  } catch (const std::exception& e) {
    fail("perception", e);
  }
}

}  // namespace agent::program
