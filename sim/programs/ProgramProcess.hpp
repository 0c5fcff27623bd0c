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

namespace simswift::programs {

struct LaunchSpec {
  std::vector<std::string> command;  // argv (placeholders allowed); empty = not launched
  std::string cwd;                   // "" = the scenario's folder
  std::vector<std::pair<std::string, std::string>> env;  // added to simswift's environment
  double stop_grace_s = 2;           // s between SIGTERM and SIGKILL at the end
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
  // leads its own process group and is killed if simswift dies
  // (PR_SET_PDEATHSIG). With `robocup_socket` (a LoLA robot's socket), the
  // child gets a mount namespace of its own in which /tmp/robocup is that
  // socket (bound onto the machine's /tmp/robocup, made once as the mount
  // point: a socket nobody listens on): an unchanged V6 program opens its own robot,
  // several side by side; the mount goes with the program (also after
  // kill -9). Throws std::runtime_error naming the program if the
  // command cannot be started (not found, not executable: the exec error;
  // the namespace refused: why).
  ProgramProcess(std::string robot, const std::vector<std::string>& argv, const std::string& cwd,
                 const std::vector<std::pair<std::string, std::string>>& env, std::string log_path,
                 double stop_grace_s, const std::string& robocup_socket = "");
  ~ProgramProcess();  // stop()
  ProgramProcess(const ProgramProcess&) = delete;
  ProgramProcess& operator=(const ProgramProcess&) = delete;

  pid_t pid() const { return pid_; }
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
  bool reaped_ = false;
  std::optional<std::string> how_;
};

}  // namespace simswift::programs
