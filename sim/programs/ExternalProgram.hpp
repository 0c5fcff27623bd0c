// A robot program in another process, attached to its body by name (the
// libagent block in named shared memory): started by hand (ExternalProgram,
// `program: external`) or by simswift (LaunchedProgram, `program: {command:
// [...]}`: ProgramProcess.hpp). Either may start before or after the
// simulator: the first tick waits up to the scenario's attach_timeout.
#pragma once

#include <memory>

#include "sim/programs/ClockPage.hpp"
#include "sim/programs/ProgramDriver.hpp"
#include "sim/programs/ProgramProcess.hpp"

namespace simswift::programs {

class ExternalProgram : public ProgramDriver {
 public:
  // attach_timeout_s: wall-clock s to wait for the first answer; `clock`:
  // the robot's clock page (the program's simulated time, docs/shim.md);
  // `view`: the robot's view held for `simswift attach` (ProgramProcess
  // without a command; its pid and folder are in the page), or null.
  ExternalProgram(RobotSlot slot, double attach_timeout_s, std::unique_ptr<ClockPage> clock,
                  std::unique_ptr<ProgramProcess> view = nullptr);
  // Waits for the first answer; on a terminal, says after 0.5 s what to
  // start. Then the clock page says Running.
  bool attach() override;
  void publishTime(int64_t tick) override { clock_->publish(tick); }
  // The run is over: the clock page says Ended (the program's waits for
  // time end, so it can see its shutdown: docs/shim.md); a view ends with
  // what runs in it, as a launched program does (SIGTERM, stop_grace, SIGKILL).
  void stop() override {
    clock_->setState(common::clock::RunState::Ended);
    if (view_) view_->stop();
  }
  // The view's wlan0 (RobotNetwork.hpp), if it has one.
  int takeNetwork() override { return view_ ? view_->takeNetwork() : -1; }
  // A program that has gone (BodySide::programGone: a V6 program restarted
  // by hand, a new gdb session) is waited for as long as the first attach,
  // saying so on stderr; RunnerError if none comes back in time.
  bool await(Step step, double timeout_s) override;

 protected:
  double attach_timeout_s_;
  std::unique_ptr<ClockPage> clock_;
  std::unique_ptr<ProgramProcess> view_;
};

class LaunchedProgram final : public ExternalProgram {
 public:
  // Starts `process` (already spawned: the factory fills its command).
  LaunchedProgram(RobotSlot slot, double attach_timeout_s, std::unique_ptr<ClockPage> clock,
                  std::unique_ptr<ProgramProcess> process);
  bool attach() override;
  // In slices of 50 ms (wall clock), checking the process between them, so
  // a crash ends the run within a slice (ProgramError), never a hang.
  bool await(Step step, double timeout_s) override;
  void checkRunning() override { check(); }
  void stop() override {
    ExternalProgram::stop();
    process_->stop();
  }
  std::string log() const override { return slot_.tag + ": " + process_->logPath(); }
  int takeNetwork() override { return process_->takeNetwork(); }

 private:
  bool awaitChecked(Step step, double timeout_s);
  void check();
  std::unique_ptr<ProgramProcess> process_;
};

}  // namespace simswift::programs
