#include "sim/programs/ProgramProcess.hpp"

#include "sim/programs/MountNamespace.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace simswift::programs {

namespace fs = std::filesystem;

namespace {

// In the forked child of a LoLA robot's program: a mount namespace of its own
// (MountNamespace.hpp) in which the robot's socket is bound onto
// /tmp/robocup (the mount point: robocupMountPoint, below). Syscalls only:
// 0, or the errno of the step that failed.
int privateRobocup(const char* socket_path, const IdMaps& maps) {
  if (const int e = enterOwnMountNamespace(maps)) return e;
  if (mount(socket_path, "/tmp/robocup", nullptr, MS_BIND, nullptr) != 0) return errno;
  return 0;
}

// A bind mount needs a file to cover: /tmp/robocup, made once when missing
// as a socket nobody listens on (what a LoLA server, names: bare, takes for
// a stale one and replaces) and left. Its errno, or 0 (also when it exists).
int robocupMountPoint() {
  struct stat st {};
  if (lstat("/tmp/robocup", &st) == 0) return 0;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strcpy(address.sun_path, "/tmp/robocup");
  const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return errno;
  const int r = bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address));
  const int e = errno;
  close(fd);
  return r == 0 || e == EADDRINUSE ? 0 : e;
}

std::string describe(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return "ended (wait status " + std::to_string(status) + ")";
}

}  // namespace

std::string ProgramProcess::fill(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (text[i] != '{') {
      out += text[i++];
      continue;
    }
    const size_t close = text.find('}', i);
    if (close == std::string::npos) throw std::runtime_error("unclosed '{' in '" + text + "'");
    const std::string name = text.substr(i + 1, close - i - 1);
    const auto it = values.find(name);
    if (it == values.end()) {
      std::string known;
      for (const auto& [k, v] : values) known += (known.empty() ? "{" : ", {") + k + "}";
      throw std::runtime_error("unknown placeholder {" + name + "} in '" + text + "' (known: " + known + ")");
    }
    out += it->second;
    i = close + 1;
  }
  return out;
}

std::string ProgramProcess::resolveCommand(const std::string& name, const std::string& base) {
  if (name.find('/') != std::string::npos) {
    if (name[0] == '/' || base.empty()) return name;
    return (fs::path(base) / name).lexically_normal().string();
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const fs::path& dir : {exe.parent_path(), exe.parent_path().parent_path()})
      if (access((dir / name).c_str(), X_OK) == 0) return (dir / name).string();
  return name;  // PATH
}

ProgramProcess::ProgramProcess(std::string robot, const std::vector<std::string>& argv, const std::string& cwd,
                               const std::vector<std::pair<std::string, std::string>>& env, std::string log_path,
                               double stop_grace_s, const std::string& robocup_socket)
    : robot_(std::move(robot)), log_path_(std::move(log_path)), stop_grace_s_(stop_grace_s) {
  if (argv.empty()) throw std::runtime_error("robot " + robot_ + ": program: empty command");
  std::error_code ec;
  if (fs::path(log_path_).has_parent_path()) fs::create_directories(fs::path(log_path_).parent_path(), ec);
  const int log = open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0)
    throw std::runtime_error("robot " + robot_ + ": cannot write the program's log " + log_path_ + ": " +
                             std::strerror(errno));
  int report[2];  // the exec's errno, if it fails (closed on a successful exec)
  if (pipe2(report, O_CLOEXEC) != 0) {
    close(log);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  // Everything the child needs, built before fork (no allocation after it).
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (const auto& [k, v] : env) env_strings.push_back(k + "=" + v);
  std::vector<char*> envp;
  for (char** e = environ; *e; ++e) {
    bool replaced = false;
    for (const auto& [k, v] : env)
      if (std::strncmp(*e, k.c_str(), k.size()) == 0 && (*e)[k.size()] == '=') replaced = true;
    if (!replaced) envp.push_back(*e);
  }
  for (std::string& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);
  const IdMaps maps = selfIdMaps();
  if (!robocup_socket.empty()) {
    if (const int e = robocupMountPoint()) {
      close(log), close(report[0]), close(report[1]);
      throw std::runtime_error("robot " + robot_ + ": cannot make /tmp/robocup for its program's view: " +
                               std::strerror(e));
    }
  }
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) {
    const int e = errno;
    close(log), close(report[0]), close(report[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(e));
  }
  if (pid_ == 0) {
    setpgid(0, 0);                     // its own group: stop() reaches its children
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // simswift killed: the program goes too
    if (getppid() != parent) _exit(127);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, STDIN_FILENO);
    int err = 0;
    // Negative: the namespace failed (the parent says so).
    if (!robocup_socket.empty()) err = -privateRobocup(robocup_socket.c_str(), maps);
    if (err == 0 && !cwd.empty() && chdir(cwd.c_str()) != 0) err = errno;
    if (err == 0) {
      execvpe(args[0], args.data(), envp.data());
      err = errno;
    }
    ssize_t w = write(report[1], &err, sizeof err);
    (void)w;
    _exit(127);
  }
  close(log);
  close(report[1]);
  int err = 0;
  ssize_t n;
  do n = read(report[0], &err, sizeof err);
  while (n < 0 && errno == EINTR);
  close(report[0]);
  if (n == static_cast<ssize_t>(sizeof err)) {
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    if (err < 0)
      throw std::runtime_error("robot " + robot_ + ": cannot give its program '" + argv[0] +
                               "' its own /tmp/robocup (mount namespace): " + std::strerror(-err));
    throw std::runtime_error("robot " + robot_ + ": cannot start its program '" + argv[0] + "'" +
                             (cwd.empty() ? "" : " in " + cwd) + ": " + std::strerror(err));
  }
}

ProgramProcess::~ProgramProcess() { stop(); }

std::string ProgramProcess::enterPrivateRobocup(const std::string& socket_path) {
  if (access(socket_path.c_str(), F_OK) != 0)
    return "its LoLA socket " + socket_path + ": " + std::strerror(errno) +
           " (start the run first: the robot's socket exists while it runs)";
  if (const int e = robocupMountPoint()) return std::string("/tmp/robocup: ") + std::strerror(e);
  const int err = privateRobocup(socket_path.c_str(), selfIdMaps());
  if (err != 0)
    return std::string("its own /tmp/robocup (mount namespace): ") + std::strerror(err) +
           " (a program that takes a socket path can be started with " + socket_path +
           " itself; or give the robot names: bare, its socket is then /tmp/robocup itself)";
  return "";
}

std::optional<std::string> ProgramProcess::ended() {
  if (how_ || reaped_) return how_;
  int status = 0;
  const pid_t r = waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    reaped_ = true;
    how_ = describe(status);
  }
  return how_;
}

std::string ProgramProcess::endedMessage() {
  const std::optional<std::string> how = ended();
  std::string m = "robot " + robot_ + ": its program (pid " + std::to_string(pid_) + ") " +
                  (how ? *how : std::string("is still running")) + "; log " + log_path_;
  const std::string last = tail(log_path_, 8);
  m += last.empty() ? " (empty)" : ", last lines:\n" + last;
  return m;
}

void ProgramProcess::stop() {
  if (pid_ <= 0 || reaped_) return;
  using Clock = std::chrono::steady_clock;
  kill(-pid_, SIGTERM);
  kill(pid_, SIGTERM);
  // Wall clock: only how long a program may take to exit, never simulation.
  const auto deadline = Clock::now() + std::chrono::duration<double>(stop_grace_s_);
  while (!ended() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (!ended()) {
    kill(-pid_, SIGKILL);
    kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    reaped_ = true;
    how_ = describe(status);
  }
  kill(-pid_, SIGKILL);  // anything it left in its group
}

std::string ProgramProcess::tail(const std::string& path, int lines) {
  std::ifstream in(path, std::ios::binary);
  if (!in || lines <= 0) return "";
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size <= 0) return "";  // empty (a program that died before writing), or unreadable
  const std::streamoff from = std::max<std::streamoff>(0, size - kTailBytes);
  in.seekg(from);
  std::string text(static_cast<size_t>(size - from), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  // Its lines, oldest first; the window's first line is cut if the window
  // starts inside the file. Trailing blank lines are not shown.
  std::vector<std::string> all;
  for (size_t start = 0;;) {
    const size_t nl = text.find('\n', start);
    all.push_back(text.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  const bool first_cut = from > 0;
  while (!all.empty() && all.back().empty()) all.pop_back();
  const size_t first = all.size() > static_cast<size_t>(lines) ? all.size() - static_cast<size_t>(lines) : 0;
  std::string out;
  for (size_t i = first; i < all.size(); ++i) {
    const std::string& l = all[i];
    const bool cut = (i == 0 && first_cut) || l.size() > kTailLineChars;
    out += (out.empty() ? "  | " : "\n  | ") + std::string(cut ? "..." : "") +
           (l.size() > kTailLineChars ? l.substr(l.size() - kTailLineChars) : l);
  }
  return out;
}

}  // namespace simswift::programs
