#include "agent/program/RobotProgram.hpp"

#include <pthread.h>

#include <algorithm>
#include <cstdio>

#include "common/libagent/SharedNames.hpp"

namespace agent::program {

using common::libagent::JointValues;
using common::libagent::SensorValues;

namespace {
void nameThisThread(const std::string& name) {
  // Linux limits thread names to 15 characters.
  pthread_setname_np(pthread_self(), name.substr(0, 15).c_str());
}

struct NullGenerator : framework::MotionGenerator {
  void tick(const SensorValues&, int64_t, JointValues&) override {}
};

ProgramConfig shorthand(int team, int player, std::unique_ptr<framework::MotionGenerator> motion,
                        std::unique_ptr<framework::PerceptionStep> perception) {
  ProgramConfig c;
  c.team = team;
  c.player = player;
  c.motion_generator = std::move(motion);
  c.perception_step = std::move(perception);
  // No generator: GeneratorModule holds the measured angles.
  if (!c.motion_generator) c.motion_generator = std::make_unique<NullGenerator>();
  return c;
}
}  // namespace

RobotProgram::RobotProgram(std::unique_ptr<BodyConnection> connection, ProgramConfig cfg)
    : conn_(std::move(connection)), tag_(common::libagent::robotTag(cfg.team, cfg.player)), cfg_(std::move(cfg)) {}

RobotProgram::RobotProgram(common::libagent::AgentConnection connection, ProgramConfig cfg)
    : RobotProgram(libagentBody(std::move(connection)), std::move(cfg)) {}

RobotProgram::RobotProgram(common::libagent::AgentConnection connection, int team, int player,
                           std::unique_ptr<framework::MotionGenerator> motion,
                           std::unique_ptr<framework::PerceptionStep> perception)
    : RobotProgram(std::move(connection), shorthand(team, player, std::move(motion), std::move(perception))) {}

RobotProgram::~RobotProgram() { join(); }

void RobotProgram::setMotion(std::unique_ptr<framework::MotionGenerator> motion) {
  if (motion_thread_.joinable()) throw std::logic_error("RobotProgram::setMotion after start");
  cfg_.motion_generator = std::move(motion);
}

void RobotProgram::start(Threading threading) {
  buildSchedule(cfg_, [this](const blackboard::ActuatorRequest& a) { pending_ = a.joints; }, conn_->camera().images(),
                conn_->cameraLens(),
                schedule_);
  schedule_.check();  // throws ModuleError before any thread starts
  if (cfg_.extensions) team_link_ = std::make_unique<comms::TeamLinkTransport>(&cfg_.extensions->team);
  // Perception runs at every frame whether or not images are rendered.
  with_perception_ = conn_->camera().hasCamera();
  threading_ = threading;
  // Announce first: the simulator decides whether to send camera frames once
  // Motion has answered its first tick, which may happen as soon as the
  // thread exists.
  conn_->announce(with_perception_);
  if (threading_ == Threading::Inline) return;
  motion_thread_ = std::thread([this] { motionLoop(); });
  if (with_perception_) perception_thread_ = std::thread([this] { perceptionLoop(); });
}

bool RobotProgram::stepMotion() {
  if (threading_ != Threading::Inline) throw std::logic_error("RobotProgram::stepMotion: the program runs its own threads");
  if (failed_ || !conn_->takeTick()) return false;
  try {
    motionStep();
    return true;
  } catch (const std::exception& e) {
    failed_ = true;
    fail("motion", e);
    return false;
  }
}

bool RobotProgram::stepPerception() {
  if (threading_ != Threading::Inline) throw std::logic_error("RobotProgram::stepPerception: the program runs its own threads");
  if (failed_ || !with_perception_ || !conn_->camera().takeFrame()) return false;
  try {
    perceptionStep();
    return true;
  } catch (const std::exception& e) {
    failed_ = true;
    fail("perception", e);
    return false;
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
  std::fprintf(stderr, "robot %s: %s %s: %s\n", tag_.c_str(), thread.c_str(),
               threading_ == Threading::Inline ? "step failed" : "thread stopped", e.what());
}

void RobotProgram::motionLoop() {
  nameThisThread(tag_ + "-motion");
  try {
    while (conn_->waitTick()) motionStep();
  } catch (const std::exception& e) {
    // No acknowledgement follows: the simulator's watchdog reports this robot.
    fail("motion", e);
  }
}

void RobotProgram::motionStep() {
  blackboard::SensorFrame s;
  s.values = conn_->readSensors();
  if (io_ && conn_->libagent()) {
    io_->standing = conn_->libagent()->block()->standing;
    io_->buttons = conn_->libagent()->buttons();
    io_->stiffen = false;
  }
  s.sim_time_us = conn_->timeUs();
  s.time = static_cast<double>(s.sim_time_us) * 1e-6;
  board_.sensors.write(s);
  if (cfg_.step_hook) cfg_.step_hook(framework::ThreadId::Motion);
  schedule_.run(framework::ThreadId::Motion, board_);  // motion -> effector
  conn_->writeActuators(pending_, io_ && io_->stiffen);
  motion_ticks_.fetch_add(1);
  if (after_tick_) after_tick_(s.values, s.sim_time_us);
}

void RobotProgram::perceptionLoop() {
  nameThisThread(tag_ + "-percept");
  try {
    while (conn_->camera().waitFrame()) perceptionStep();
  } catch (const std::exception& e) {
    fail("perception", e);
  }
}

void RobotProgram::perceptionStep() {
  const common::libagent::CameraFrame& cf = conn_->camera().frame();
  // The Motion thread is between ticks while a frame is processed (the
  // body side waits for its answer before posting a frame), so the
  // sensors section holds the sensors of the tick at frame time.
  blackboard::FrameInfo f;
  f.sim_time_us = cf.sim_time_us;
  f.frame_index = cf.frame_index;
  f.time = static_cast<double>(cf.sim_time_us) * 1e-6;
  f.dt = last_frame_time_ < 0 ? 0 : f.time - last_frame_time_;
  last_frame_time_ = f.time;
  f.sensors = board_.sensors.read().values;
  f.num_observations = std::clamp<int32_t>(cf.num_observations, 0, common::libagent::kMaxObservations);
  std::copy(cf.observations, cf.observations + f.num_observations, f.observations);
  f.images_valid = cf.images_valid != 0;
  board_.frame.write(f);
  // The devices in (the simulator writes neither while a frame is processed).
  blackboard::GameControllerData gc;
  gc.present = cfg_.extensions != nullptr;
  if (gc.present) gc.block = cfg_.extensions->game;
  board_.game_controller.write(gc);
  blackboard::TeamInbox inbox;
  inbox.connected = team_link_ != nullptr;
  if (team_link_) inbox.packets = team_link_->receive();
  board_.team_inbox.write(inbox);
  if (cfg_.step_hook) cfg_.step_hook(framework::ThreadId::Perception);
  schedule_.run(framework::ThreadId::Perception, board_);
  // A packet the transport refuses (outbox full) is lost, as a UDP send's.
  if (team_link_)
    for (const std::vector<uint8_t>& packet : board_.team_outbox.read().packets) team_link_->send(packet);
  perception_frames_.fetch_add(1);
  conn_->camera().perceptionDone();
}

}  // namespace agent::program
