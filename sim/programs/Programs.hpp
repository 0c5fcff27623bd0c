// The program side of a run: the factory that gives every robot its
// ProgramDriver (ProgramDriver.hpp) from what the Runner hands it of the
// scenario (ProgramEntry, ProgramRun; it reads no scenario), and what tests,
// benchmarks, tools and the public API set before the run starts (a builtin
// robot's Motion step, behaviour, Motion configuration, Perception step,
// step hook, threading, an API controller). The Runner owns one
// (Runner::programs()) and drives the robots only through their drivers.
#pragma once

#include <functional>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent/program/ScriptedMotion.hpp"
#include "common/clock/ClockPage.hpp"
#include "agent/program/RobotProgram.hpp"
#include "sim/programs/BuiltinProgram.hpp"
#include "sim/programs/ClockPage.hpp"
#include "sim/programs/ProgramDriver.hpp"
#include "sim/programs/ProgramProcess.hpp"
#include "sim/programs/ProgramSpec.hpp"

namespace simswift::programs {

// How builtin programs run: on named threads or inline on the simulator's
// thread (agent/program/RobotProgram.hpp). The rest of sim/ and app/ name it
// here: they reach the robot program only through sim/programs.
using Threading = agent::program::Threading;

// One robot's program as the scenario gives it (the Runner makes one per
// robot from its RobotSpec).
struct ProgramEntry {
  RobotSlot slot;
  ProgramKind kind = ProgramKind::Builtin;
  LaunchSpec launch;                 // external: launched when it has a command
  std::string v4l2_block;            // launched or external: its cameras' V4L2 device block ("" = none; sim/bridge/V4l2Devices)
  agent::program::RobotSetup setup;  // its identity given (robotSetup)
};

// The run's settings the programs need (the scenario's; no defaults here).
struct ProgramRun {
  double attach_timeout_s = 0;  // wall-clock s to wait for an external program's first answer
  std::string program_logs;     // launched programs' logs and {config} files
  std::string base_dir;         // where a launched command's relative path resolves first
  int64_t tick_us = 10000;      // the bodies' cycle (a program's clock page advances by it)
  int64_t clock_epoch_ns = common::clock::kDefaultRealtimeEpochNs;  // REALTIME at t = 0 (docs/shim.md)
};

class Programs {
 public:
  explicit Programs(int num_robots);
  ~Programs();
  Programs(const Programs&) = delete;
  Programs& operator=(const Programs&) = delete;

  // Before the run starts: replace a builtin robot's Motion step (robot
  // index in scenario order), e.g. a test's motion generator.
  void setMotionGenerator(int robot, std::unique_ptr<agent::framework::MotionGenerator> motion);
  // Before the run starts: give a builtin robot this behaviour module (the
  // Perception thread's behaviour slot, agent/program/ModuleOrder.cpp; e.g.
  // agent/behaviour/RequestedBehaviour.hpp, through which a test, bench or
  // tool plays Behaviour). It replaces the scenario robot's behaviour,
  // action script or held posture; Motion is then the standard Motion module
  // (MotionThreadModule, with setMotionConfig's configuration), reading the
  // motion request the behaviour writes. The start throws RunnerError if the
  // robot also has a setMotionGenerator (nothing would read the request).
  void setBehaviour(int robot, std::unique_ptr<agent::framework::Module> behaviour);
  // Before the run starts: a builtin robot's Motion module configuration
  // (ProgramConfig::motion: walk, kick, get-ups, fall handling; default
  // agent::motion::MotionConfig()).
  void setMotionConfig(int robot, const agent::motion::MotionConfig& config);
  // Before the run starts: replace a builtin robot's Perception step.
  void setPerceptionStep(int robot, std::unique_ptr<agent::framework::PerceptionStep> perception);
  // Before the run starts: a hook each of a builtin robot's threads calls
  // before every step (ProgramConfig::step_hook; tests jitter thread timing with it).
  void setStepHook(int robot, std::function<void(agent::framework::ThreadId)> hook);
  // Before the run starts: the public API's controller as the robot's
  // Motion step (ApiController; the robot must be builtin).
  void setController(int robot, RawController controller);
  // The same, with libagent's `standing`, buttons and STIFFEN (replaces a plain controller).
  void setLibagentController(int robot, RawLibagentController controller);
  // Before the run starts: builtin programs on named threads (default) or
  // inline on the simulator's thread (sim/runner/Runner.hpp).
  void setThreading(agent::program::Threading threading);
  agent::program::Threading threading() const { return threading_; }

  // The Runner's start, after the bodies: one driver per robot, in scenario
  // order (builtin programs composed and started, launched programs'
  // processes started with their {config} files). Throws RunnerError,
  // ProgramError.
  void build(const ProgramRun& run, const std::vector<ProgramEntry>& robots);
  bool built() const { return built_; }
  ProgramDriver& driver(int i) { return *robots_[i].driver; }
  const ProgramDriver& driver(int i) const { return *robots_[i].driver; }
  int size() const { return static_cast<int>(robots_.size()); }

  // Robot i's builtin program (null for an external one, or before the
  // start); read its Blackboard between ticks (tests, benchmarks).
  agent::program::RobotProgram* program(int i) const;
  // Launched programs' log files, in scenario order ("t19p2: simswift-logs/t19p2.log").
  std::vector<std::string> logs() const;
  // Every driver stopped, then every builtin program joined (the body
  // sides shut down first). The drivers stay: their Blackboards can still
  // be read.
  void shutdown();

 private:
  struct Robot {
    std::unique_ptr<agent::framework::MotionGenerator> motion_override;
    std::unique_ptr<agent::framework::Module> behaviour_override;
    std::optional<agent::motion::MotionConfig> motion_config;
    std::unique_ptr<agent::framework::PerceptionStep> perception_override;
    std::function<void(agent::framework::ThreadId)> step_hook;
    RawController controller;
    RawLibagentController libagent_controller;
    std::shared_ptr<LibagentExtras> libagent_io;  // shared by that controller and its program
    std::unique_ptr<ProgramDriver> driver;
  };
  Robot& overrideSlot(int robot, const char* what);
  std::unique_ptr<ProgramDriver> makeBuiltin(const ProgramEntry& e, Robot& r);
  std::unique_ptr<ProgramDriver> makeLaunched(const ProgramRun& run, const ProgramEntry& e);
  std::unique_ptr<ProgramDriver> makeExternal(const ProgramRun& run, const ProgramEntry& e);
  static std::unique_ptr<ClockPage> clockPage(const ProgramRun& run, const ProgramEntry& e,
                                              const ClockPage::View& view = {});
  // How a launched LoLA program sees its socket: `robocup` to bind onto
  // /tmp/robocup in its own mount namespace (empty: none needed), or the
  // socket's real path as {socket} where the machine gives no namespace.
  struct LolaView {
    std::string robocup;
    std::string socket_placeholder;
  };
  static LolaView lolaView(const ProgramEntry& e);
  static ProgramView programView(const ProgramEntry& e, const std::filesystem::path& logs, const std::string& robocup,
                                 const std::vector<std::string>& argv, const std::string& cwd,
                                 const std::vector<std::pair<std::string, std::string>>& env,
                                 const std::string& config);

  std::vector<Robot> robots_;
  agent::program::Threading threading_ = agent::program::Threading::Named;
  bool built_ = false;
};

}  // namespace simswift::programs
