// `simswift attach` started by a test as a user would start it by hand:
// the build's simswift, its output (stdout and stderr) in a log file.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace simswift::testing {

// Forks `simswift attach --team T --player P -- COMMAND...`; its pid.
inline pid_t startAttach(int team, int player, const std::vector<std::string>& command, const std::string& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) ::dup2(fd, 1), ::dup2(fd, 2);
    std::vector<std::string> args = {std::string(SIMSWIFT_BINARY_DIR) + "/simswift", "attach", "--team",
                                     std::to_string(team), "--player", std::to_string(player), "--"};
    args.insert(args.end(), command.begin(), command.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

// Waits for `pid`: its exit status, or 128 + the signal that killed it.
inline int exitCodeOf(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace simswift::testing
