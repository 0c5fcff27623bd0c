// A robot program simswift starts itself (`program: {command: [...]}`): its
// process, started with the robot's names and setup filled into the command,
// its output in a log file, watched while the run waits for it, and stopped
// at the end (SIGTERM, then SIGKILL after stop_grace s), reaped.
//
//   program: {command: [simswift-agent, --config, "{config}"],   # argv
//             cwd: DIR, env: {KEY: VALUE}, stop_grace: 2}
//
// Placeholders in the command, cwd and env values: {team}, {player}; for a
// libagent body {number} (libagent's N = team x 11 + player), {memory},
// {semaphore} (the robot's libagent object names), {extension} (simswift's
// extension object); for a LoLA body {socket} (its socket as the program
// sees it: /tmp/robocup in its own mount namespace, below); {seed} (the program's seed, as a builtin program gets it), {config} (a
// file with the robot's setup as the builtin program gets it:
// agent/program/RobotSetup.hpp). A relative command path, or a bare name
// found beside the simswift executable (simswift-agent), resolves against
// the scenario's folder or that folder; other bare names go through PATH.
#pragma once

#include <sys/types.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/programs/ProgramView.hpp"

namespace simswift::programs {

struct LaunchSpec {
  std::vector<std::string> command;  // argv (placeholders allowed); empty = not launched
  std::string cwd;                   // "" = the scenario's folder
  std::vector<std::pair<std::string, std::string>> env;  // added to simswift's environment
  double stop_grace_s = 2;           // s between SIGTERM and SIGKILL at the end
  std::vector<FileEntry> files;      // the robot's files beyond the defaults (ProgramView.hpp)
  // Its own network (wlan0, RobotNetwork.hpp): Auto where the machine gives
  // one, On (refused where it does not), Off (the machine's network).
  enum class Network { Auto, On, Off } network = Network::Auto;
  bool launched() const { return !command.empty(); }
  // Whether the placeholder {name} appears in the command or in an
  // environment value.
  bool names(const std::string& name) const {
    const std::string p = "{" + name + "}";
    for (const std::string& a : command)
      if (a.find(p) != std::string::npos) return true;
    for (const auto& kv : env)
      if (kv.second.find(p) != std::string::npos) return true;
    return false;
  }
};

class ProgramProcess {
 public:
  // Starts `argv` (placeholders already filled) in `cwd` with `env` added,
  // stdout and stderr into `log_path` (created; its folder too). The child
  // runs under a small init of simswift's (pid() is the init's), which
  // leads its own process group, is killed if simswift dies
  // (PR_SET_PDEATHSIG), forwards SIGTERM/SIGINT/SIGHUP to the program, reaps
  // and reports how the program ended. With `view.isolate` the init is PID 1
  // of a PID namespace of its own (its death ends every process in it: a
  // wrapper script's children too) and gives the program the view of
  // ProgramView.hpp (its own /tmp, /tmp/robocup, /home/nao, the robot's
  // files). Throws std::runtime_error naming the program if the command
  // cannot be started (not found, not executable: the exec error; the
  // namespace or a mount refused: why). `argv` empty with `view.isolate`:
  // the init holds the view and starts nothing (an external robot's, for
  // `simswift attach`: JoinView.hpp); stop() then sends SIGTERM to
  // every process in it and ends it when none is left (SIGKILL after the grace).
  ProgramProcess(std::string robot, const std::vector<std::string>& argv, const std::string& cwd,
                 const std::vector<std::pair<std::string, std::string>>& env, std::string log_path,
                 double stop_grace_s, const ProgramView& view = {});
  ~ProgramProcess();  // stop()
  ProgramProcess(const ProgramProcess&) = delete;
  ProgramProcess& operator=(const ProgramProcess&) = delete;

  pid_t pid() const { return pid_; }
  // The robot's wlan0 (a TAP descriptor, non-blocking) with a network view,
  // handed over once (the caller owns it); -1 otherwise.
  int takeNetwork() {
    const int fd = net_fd_;
    net_fd_ = -1;
    return fd;
  }
  const std::string& logPath() const { return log_path_; }
  // Empty while it runs; once it has ended, how: "exited with status 3",
  // "killed by signal 11 (Segmentation fault)". Non-blocking (reaps).
  std::optional<std::string> ended();
  // The run's error for a program that ended early: robot, how it ended,
  // the log's path and its last lines ("(empty)" if it wrote nothing).
  std::string endedMessage();
  // SIGTERM to its group, SIGKILL after the grace, reaped. Idempotent.
  void stop();

  // The log's last `lines` lines, each indented "  | " (at most the last
  // kTailBytes of the file read; a line longer than kTailLineChars, or cut
  // by that window, shows its end after "..."); "" for an empty or missing
  // log or one of blank lines.
  static constexpr long kTailBytes = 4096;
  static constexpr size_t kTailLineChars = 240;
  static std::string tail(const std::string& path, int lines);
  // Replaces {name} by values[name]; an unknown {name} is an error naming it.
  static std::string fill(const std::string& text, const std::map<std::string, std::string>& values);
  // This process enters what a launched LoLA program gets (above): its own
  // mount namespace, /tmp/robocup bound to `socket_path`
  // (`simswift attach`, for a program started by hand). Empty on success,
  // else why not.
  static std::string enterPrivateRobocup(const std::string& socket_path);
  // The executable for command[0]: a path with '/' resolves against `base`;
  // a bare name is taken from beside this executable if there, else left to PATH.
  static std::string resolveCommand(const std::string& name, const std::string& base);

 private:
  std::string robot_;
  std::string log_path_;
  double stop_grace_s_;
  pid_t pid_ = -1;
  int status_fd_ = -1;  // the init writes the program's wait status here
  int life_fd_ = -1;
  int net_fd_ = -1;     // the robot's wlan0, until taken    // held while simswift lives: the init sees it closed if simswift died before its prctl
  bool reaped_ = false;
  std::string reapedHow(int init_status);
  std::optional<std::string> how_;
};

}  // namespace simswift::programs
