#include "sim/programs/ExternalProgram.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "sim/bridge/BodySide.hpp"
#include "sim/programs/Errors.hpp"

namespace simswift::programs {

namespace {

// Seconds in messages, as printf's %g writes them.
std::string seconds(double s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

}  // namespace

ExternalProgram::ExternalProgram(RobotSlot slot, double attach_timeout_s, std::unique_ptr<ClockPage> clock,
                                 std::unique_ptr<ProgramProcess> view)
    : ProgramDriver(std::move(slot)),
      attach_timeout_s_(attach_timeout_s),
      clock_(std::move(clock)),
      view_(std::move(view)) {}

bool ExternalProgram::attach() {
  bridge::BodySide& host = *slot_.host;
  if (host.waitAnswer(0.5)) {
    clock_->setState(common::clock::RunState::Running);
    return true;
  }
  std::fprintf(stderr, "waiting for robot %s on %s: %s\n", slot_.tag.c_str(), host.endpoint().c_str(),
               host.attachHint().c_str());
  if (!host.waitAnswer(attach_timeout_s_)) {
    std::ostringstream m;
    m << "robot " << slot_.tag << ": no robot program answered on " << host.endpoint() << " within "
      << attach_timeout_s_ << " s (program: external: " << host.attachHint()
      << "; a program still running from an earlier run holds that run's removed objects and never "
         "answers here: restart it)";
    throw RunnerError(m.str());
  }
  clock_->setState(common::clock::RunState::Running);
  return true;
}

bool ExternalProgram::await(Step step, double timeout_s) {
  bridge::BodySide& host = *slot_.host;
  if (step != Step::Motion) return ProgramDriver::await(step, timeout_s);
  // Gone before the wait, or during it (a program that read this cycle's
  // packet and then ended, or whose exit came after the packet was sent):
  // waited for as for its first attach. Connected and silent: the watchdog's.
  if (!host.programGone()) {
    if (ProgramDriver::await(step, timeout_s)) return true;
    if (!host.programGone()) return false;
  }
  std::fprintf(stderr, "robot %s: its program disconnected; waiting up to %g s (attach_timeout) for it to connect "
               "again on %s\n", slot_.tag.c_str(), attach_timeout_s_, host.endpoint().c_str());
  if (!host.waitAnswer(attach_timeout_s_)) {
    std::ostringstream m;
    m << "robot " << slot_.tag << ": its program disconnected and none connected again on " << host.endpoint()
      << " within attach_timeout " << attach_timeout_s_ << " s (" << host.attachHint() << ")";
    throw RunnerError(m.str());
  }
  std::fprintf(stderr, "robot %s: its program connected again\n", slot_.tag.c_str());
  return true;
}

LaunchedProgram::LaunchedProgram(RobotSlot slot, double attach_timeout_s, std::unique_ptr<ClockPage> clock,
                                 std::unique_ptr<ProgramProcess> process)
    : ExternalProgram(std::move(slot), attach_timeout_s, std::move(clock)), process_(std::move(process)) {}

bool LaunchedProgram::attach() {
  if (!awaitChecked(Step::Motion, attach_timeout_s_))
    throw ProgramError("robot " + slot_.tag + ": its program (pid " + std::to_string(process_->pid()) +
                           ") did not answer on " + slot_.host->endpoint() + " within attach_timeout " +
                           seconds(attach_timeout_s_) + " s; log " + process_->logPath(),
                       slot_.tag + ": program did not attach within " +
                           seconds(attach_timeout_s_) + " s");
  clock_->setState(common::clock::RunState::Running);
  return true;
}

bool LaunchedProgram::await(Step step, double timeout_s) { return awaitChecked(step, timeout_s); }

bool LaunchedProgram::awaitChecked(Step step, double timeout_s) {
  constexpr double kSlice = 0.05;  // s
  for (double waited = 0; waited < timeout_s; waited += kSlice) {
    if (ProgramDriver::await(step, std::min(kSlice, timeout_s - waited))) return true;
    check();
  }
  return false;
}

void LaunchedProgram::check() {
  if (process_->ended()) throw ProgramError(process_->endedMessage(), slot_.tag + ": program " + *process_->ended());
}

}  // namespace simswift::programs
