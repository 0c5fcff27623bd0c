#include "sim/programs/BuiltinProgram.hpp"

#include <cstring>

#include "sim/bridge/BodyHost.hpp"
#include "sim/programs/FindBallObserver.hpp"
#include "sim/programs/Errors.hpp"

namespace simswift::programs {

namespace al = common::libagent;
namespace ap = agent::program;

BuiltinProgram::BuiltinProgram(RobotSlot slot, ap::ProgramConfig config, ap::Threading threading)
    : ProgramDriver(std::move(slot)) {
  // Its body connection (agent/program/BodyConnection.hpp): libagent's
  // block, or LoLA's socket (connected as a V6 program connects, the
  // extension object in this process for the camera frames).
  std::unique_ptr<ap::BodyConnection> body;
  if (auto* host = dynamic_cast<bridge::BodyHost*>(slot_.host)) {
    al::AgentConnection conn = host->connect();
    conn.setImages(host->images());
    body = ap::libagentBody(std::move(conn));
  } else {
    al::AgentConnection camera = al::AgentConnection::extensionOnly(slot_.host->extension());
    camera.setImages(slot_.host->images());
    try {
      body = ap::lolaBody(common::lola::LolaConnection::connect(slot_.host->endpoint(), 1.0), std::move(camera));
    } catch (const common::lola::LolaError& e) {
      throw RunnerError("robot " + slot_.tag + ": " + e.what());
    }
  }
  program_ = std::make_unique<ap::RobotProgram>(std::move(body), std::move(config));
  program_->start(threading);
}

bool BuiltinProgram::findBallView(sim::views::FindBallViewData& out) const {
  const agent::blackboard::FindBallInfo info = program_->board().findball.read();
  if (!info.active) return false;
  out = viewFromInfo(info, slot_.player, slot_.tag);
  return true;
}

// The Blackboard's ball, localisation and findball sections (mm -> m).
bool BuiltinProgram::belief(Belief& out) const {
  agent::blackboard::Blackboard& b = program_->board();
  const agent::blackboard::BallEstimate ball = b.ball.read();
  const agent::blackboard::LocalisationEstimate loc = b.localisation.read();
  out.ball_known = ball.valid || ball.team_valid;
  out.ball_x = (ball.valid ? ball.x : ball.team_x) / 1000.0;
  out.ball_y = (ball.valid ? ball.y : ball.team_y) / 1000.0;
  out.x = loc.pose.x / 1000.0;
  out.y = loc.pose.y / 1000.0;
  out.theta = loc.pose.theta;
  const agent::blackboard::FindBallInfo fb = b.findball.read();
  out.behaviour = fb.active ? std::string(fb.activity, strnlen(fb.activity, sizeof fb.activity)) : "";
  return true;
}

ThreadedProgram::ThreadedProgram(RobotSlot slot, ap::ProgramConfig config)
    : BuiltinProgram(std::move(slot), std::move(config), ap::Threading::Named) {}

InlineProgram::InlineProgram(RobotSlot slot, ap::ProgramConfig config)
    : BuiltinProgram(std::move(slot), std::move(config), ap::Threading::Inline) {}

void InlineProgram::posted(Step step, int64_t tick) {
  const bool motion = step == Step::Motion;
  if (motion ? program_->stepMotion() : program_->stepPerception()) return;
  const std::string error = program_->error();
  throw WatchdogError("robot " + slot_.tag + ": " + (motion ? "motion" : "perception") + " step " +
                              (error.empty() ? "found nothing posted (inline)" : "failed: " + error) + " (tick " +
                              std::to_string(tick) + ")");
}

namespace {

// The controller as the program's Motion step (the public API's types are
// libagent 2017's layout: app/api/Simulation.cpp adapts them).
class ControllerMotion : public agent::framework::MotionGenerator {
 public:
  explicit ControllerMotion(RawController c) : c_(std::move(c)) {}
  void tick(const al::SensorValues& sensors, int64_t, al::JointValues& out) override { c_(sensors, out); }

 private:
  RawController c_;
};

// The libagent controller: the extras the program filled for this step.
class LibagentControllerMotion : public agent::framework::MotionGenerator {
 public:
  LibagentControllerMotion(RawLibagentController c, std::shared_ptr<LibagentExtras> io)
      : c_(std::move(c)), io_(std::move(io)) {}
  void tick(const al::SensorValues& sensors, int64_t, al::JointValues& out) override { c_(sensors, out, *io_); }

 private:
  RawLibagentController c_;
  std::shared_ptr<LibagentExtras> io_;
};

}  // namespace

ApiController::ApiController(RobotSlot slot, ap::ProgramConfig config)
    : InlineProgram(std::move(slot), std::move(config)) {}

std::unique_ptr<agent::framework::MotionGenerator> ApiController::motionStep(RawController c) {
  return std::make_unique<ControllerMotion>(std::move(c));
}

std::unique_ptr<agent::framework::MotionGenerator> ApiController::motionStep(RawLibagentController c,
                                                                              std::shared_ptr<LibagentExtras> io) {
  return std::make_unique<LibagentControllerMotion>(std::move(c), std::move(io));
}

}  // namespace simswift::programs
