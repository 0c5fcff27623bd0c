#include "sim/programs/ProgramProcess.hpp"

#include "sim/programs/MountNamespace.hpp"
#include "sim/programs/RobotNetwork.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/syscall.h>
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

// ---- The init a launched program runs under (see the header) ----
// Runs between clone and exec in a copy of a multi-threaded process:
// syscalls and async-signal-safe calls only, nothing allocated.

// What the init needs, all built before the clone.
struct InitPlan {
  char** argv;
  char** envp;
  const char* cwd;  // null = simswift's
  int log, report, status, life, life_write;
  bool isolate;
  const IdMaps* maps;
  const std::vector<MountOp>* mounts;
  uint32_t net_address;  // 0: no network of its own
  int net_sock;          // where wlan0's descriptor goes
  int hold_patience_ms;  // a held view (argv null): holdView
};

// A mount that failed is reported as -(kViewStepBase + index << 12 + errno);
// the network, as -(kNetStepBase + errno).
constexpr int kViewStepBase = 1 << 20;
constexpr int kNetStepBase = 1 << 19;

// The program's pid, for the init's signal forwarding.
volatile sig_atomic_t g_program = 0;

void forward(int sig) {
  if (g_program > 0) kill(static_cast<pid_t>(g_program), sig);
}

// clone(2) without glibc's fork handlers: as fork() when flags are SIGCHLD;
// the child then makes only syscalls (above), so no lock another thread held
// matters.
pid_t rawClone(unsigned long flags) {
  return static_cast<pid_t>(syscall(SYS_clone, flags, nullptr, nullptr, nullptr, nullptr));
}

[[noreturn]] void reportAndExit(int fd, int code) {
  ssize_t w = write(fd, &code, sizeof code);
  (void)w;
  _exit(127);
}

// Closes every descriptor but the sorted `keep` (the init never execs, so
// close-on-exec descriptors of simswift, its sockets, would stay open in it).
void closeAllBut(int* keep, int n) {
  std::sort(keep, keep + n);
  unsigned from = 0;
  for (int i = 0; i < n; ++i) {
    if (static_cast<unsigned>(keep[i]) > from) close_range(from, static_cast<unsigned>(keep[i]) - 1, 0);
    from = static_cast<unsigned>(keep[i]) + 1;
  }
  close_range(from, ~0U, 0);
}

[[noreturn]] void runProgram(const InitPlan& p) {
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) signal(sig, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the init gone: the program too (also without a PID namespace)
  close(p.status);
  close(p.life);
  if (p.cwd && chdir(p.cwd) != 0) reportAndExit(p.report, errno);
  execvpe(p.argv[0], p.argv, p.envp);
  reportAndExit(p.report, errno);
}

// A view held for programs started by hand (`simswift attach`, argv
// null): the init starts nothing; it reaps what ends in its PID namespace
// and, told to end (stop(), once the run is over: the robot's socket
// closed, its clock Ended), gives what runs in it `patience_ms` to end by
// itself (a program that ends when its body goes, gdb with it; gdb 13 told
// SIGTERM while its program exits faults), then passes SIGTERM to every
// process in it, and ends when none is left (or at stop()'s SIGKILL); its
// end ends the rest.
volatile sig_atomic_t g_hold_end = 0;

void endHold(int) { g_hold_end = 1; }

[[noreturn]] void holdView(const InitPlan& p) {
  struct sigaction sa {};
  sa.sa_handler = endHold;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaction(sig, &sa, nullptr);
  close(p.report);  // set up: the parent reads the pipe's end
  int waited_ms = 0;  // since told to end
  bool told = false;
  for (;;) {
    while (waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    if (g_hold_end) {
      // In a PID namespace -1 is every process in it but this init.
      if (kill(-1, 0) != 0 && errno == ESRCH) _exit(0);
      if (!told && waited_ms >= p.hold_patience_ms) {
        kill(-1, SIGTERM);
        told = true;
      }
      waited_ms += 10;
    }
    // Wall clock: only how often the init looks; simswift gone ends it.
    pollfd pf{p.life, POLLIN, 0};
    if (poll(&pf, 1, g_hold_end ? 10 : 200) > 0 && (pf.revents & (POLLHUP | POLLERR))) _exit(0);
  }
}

[[noreturn]] void runInit(const InitPlan& p, bool new_user) {
  setpgid(0, 0);                     // its own group: stop() reaches the program and its children
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // simswift killed: the init, and with it the namespace, goes too
  close(p.life_write);
  int keep[] = {p.log, p.report, p.status, p.life, p.net_sock};
  closeAllBut(keep, p.net_sock >= 0 ? 5 : 4);
  // simswift died before the prctl: every write end of `life` is closed.
  pollfd pf{p.life, POLLIN, 0};
  if (poll(&pf, 1, 0) > 0 && (pf.revents & POLLHUP)) _exit(127);
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  if (p.isolate) {
    const int e = new_user ? enterMountNamespaceInNewUser(*p.maps) : enterOwnMountNamespace(*p.maps);
    if (e != 0) reportAndExit(p.report, -e);
    if (p.net_address != 0)
      if (const int n = enterRobotNetwork(p.net_address, p.net_sock)) reportAndExit(p.report, -(kNetStepBase + (n & 0xfff)));
  }
  dup2(p.log, STDOUT_FILENO);
  dup2(p.log, STDERR_FILENO);
  close(p.log);
  const int devnull = open("/dev/null", O_RDONLY);
  if (devnull >= 0) dup2(devnull, STDIN_FILENO), close(devnull);
  if (p.isolate) {
    size_t i = 0;
    if (const int e = applyView(*p.mounts, &i)) reportAndExit(p.report, -(kViewStepBase + (static_cast<int>(i) << 12) + (e & 0xfff)));
  }
  if (!p.argv) holdView(p);
  struct sigaction sa {};
  sa.sa_handler = forward;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaction(sig, &sa, nullptr);
  const pid_t program = rawClone(SIGCHLD);
  if (program == 0) runProgram(p);
  if (program < 0) reportAndExit(p.report, errno);
  g_program = program;
  close(p.report);  // the program's copy closes on its exec
  // Reap every child (as PID 1 also the orphans); the program's end is the init's.
  for (;;) {
    int st = 0;
    const pid_t w = waitpid(-1, &st, 0);
    if (w == program) {
      ssize_t n = write(p.status, &st, sizeof st);
      (void)n;
      _exit(0);
    }
    if (w < 0 && errno == ECHILD) _exit(0);
  }
}

// Starts the init (as PID 1 of new PID, and when not root user, namespaces
// with `isolate`); the caller's pid of it, or -1 (errno).
pid_t cloneInit(const InitPlan& p) {
  unsigned long flags = SIGCHLD;
  bool new_user = false;
  if (p.isolate) {
    flags |= CLONE_NEWPID;
    if (geteuid() != 0) flags |= CLONE_NEWUSER, new_user = true;
  }
  pid_t pid = rawClone(flags);
  if (pid < 0 && p.isolate && !new_user && errno == EPERM) {
    new_user = true;  // root that may not: as enterOwnMountNamespace does
    pid = rawClone(flags | CLONE_NEWUSER);
  }
  if (pid == 0) runInit(p, new_user);
  return pid;
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
                               double stop_grace_s, const ProgramView& view)
    : robot_(std::move(robot)), log_path_(std::move(log_path)), stop_grace_s_(stop_grace_s) {
  if (argv.empty() && !view.isolate) throw std::runtime_error("robot " + robot_ + ": program: empty command");
  const std::string what = argv.empty() ? std::string("view (held for simswift attach)") : "program '" + argv[0] + "'";
  std::error_code ec;
  if (fs::path(log_path_).has_parent_path()) fs::create_directories(fs::path(log_path_).parent_path(), ec);
  // Everything the init and the program need, built before the clone (no
  // allocation after it).
  std::vector<MountOp> mounts;
  try {
    mounts = planView(view);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("robot " + robot_ + ": " + e.what());
  }
  const int log = open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0)
    throw std::runtime_error("robot " + robot_ + ": cannot write the program's log " + log_path_ + ": " +
                             std::strerror(errno));
  // report: the exec's errno (or a namespace step's, negative), closed on a
  // successful exec; status: the program's wait status, from the init;
  // life: its write end stays with simswift.
  int report[2], status[2], life[2];
  if (pipe2(report, O_CLOEXEC) != 0) {
    close(log);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  if (pipe2(status, O_CLOEXEC) != 0 || pipe2(life, O_CLOEXEC) != 0) {
    close(log), close(report[0]), close(report[1]);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
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
  // Under its own PID namespace the program cannot see simswift's pid:
  // simswift's own client (common/libagent/Liveness.cpp) is told so.
  if (view.isolate) env_strings.push_back("SIMSWIFT_PID_NAMESPACE_OF_PROGRAM=1");
  for (std::string& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);
  const IdMaps maps = selfIdMaps();
  int net[2] = {-1, -1};  // wlan0's descriptor, from the init
  if (view.isolate && view.network_address != 0 && socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, net) != 0) {
    const int e = errno;
    close(log), close(report[0]), close(report[1]), close(status[0]), close(status[1]), close(life[0]), close(life[1]);
    throw std::runtime_error(std::string("socketpair: ") + std::strerror(e));
  }
  const InitPlan plan{argv.empty() ? nullptr : args.data(), envp.data(), cwd.empty() ? nullptr : cwd.c_str(), log, report[1], status[1],
                      life[0], life[1], view.isolate, &maps, &mounts,
                      view.isolate ? view.network_address : 0, net[1],
                      static_cast<int>(stop_grace_s * 1000 / 2)};  // half the grace: the rest is SIGTERM's
  pid_ = cloneInit(plan);
  const int clone_errno = errno;
  if (net[1] >= 0) close(net[1]);
  if (net[0] >= 0) {
    if (pid_ > 0) net_fd_ = receiveRobotNetwork(net[0]);
    close(net[0]);
  }
  close(log);
  close(report[1]);
  close(status[1]);
  close(life[0]);
  status_fd_ = status[0];
  fcntl(status_fd_, F_SETFL, O_NONBLOCK);
  life_fd_ = life[1];
  if (pid_ < 0) {
    close(report[0]);
    throw std::runtime_error("robot " + robot_ + ": cannot start its program" +
                             (view.isolate ? " in PID and user namespaces of its own" : "") + ": clone: " +
                             std::strerror(clone_errno));
  }
  int err = 0;
  ssize_t n;
  do n = read(report[0], &err, sizeof err);
  while (n < 0 && errno == EINTR);
  close(report[0]);
  if (n == static_cast<ssize_t>(sizeof err)) {
    int st = 0;
    waitpid(pid_, &st, 0);
    reaped_ = true;
    if (net_fd_ >= 0) close(net_fd_), net_fd_ = -1;
    if (err < 0 && -err >= kNetStepBase && -err < kViewStepBase)
      throw std::runtime_error("robot " + robot_ + ": cannot give its " + what +
                               " a network of its own (wlan0 in a network namespace): " +
                               std::strerror(-err - kNetStepBase));
    if (err < 0 && -err >= kViewStepBase) {
      const size_t i = static_cast<size_t>(-err - kViewStepBase) >> 12;
      const int e = (-err - kViewStepBase) & 0xfff;
      throw std::runtime_error("robot " + robot_ + ": cannot give its " + what + " " +
                               (i < mounts.size() ? mounts[i].what : std::string("its view")) + ": mount: " +
                               std::strerror(e));
    }
    if (err < 0)
      throw std::runtime_error("robot " + robot_ + ": cannot give its " + what +
                               " its own /tmp (mount namespace): " + std::strerror(-err));
    throw std::runtime_error("robot " + robot_ + ": cannot start its " + what +
                             (cwd.empty() ? "" : " in " + cwd) + ": " + std::strerror(err));
  }
}

ProgramProcess::~ProgramProcess() {
  stop();
  if (status_fd_ >= 0) close(status_fd_);
  if (life_fd_ >= 0) close(life_fd_);
  if (net_fd_ >= 0) close(net_fd_);
}

std::string ProgramProcess::reapedHow(int init_status) {
  int st = 0;
  if (status_fd_ >= 0 && read(status_fd_, &st, sizeof st) == static_cast<ssize_t>(sizeof st)) return describe(st);
  return describe(init_status);
}

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
    how_ = reapedHow(status);
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
    how_ = reapedHow(status);
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
