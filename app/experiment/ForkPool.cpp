#include "app/experiment/ForkPool.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "sim/bridge/Cleanup.hpp"
#include "app/experiment/BatchError.hpp"
#include "app/experiment/Files.hpp"
#include "app/experiment/PrivateShm.hpp"
#include "sim/world/ConfigError.hpp"

namespace simswift::experiment {

namespace {

// The pool's handler while it runs: none of these signals is delivered
// (they are blocked and taken by sigwaitinfo); it only keeps an ignored
// SIGINT from being discarded, and SIGCHLD from meaning auto-reaped children.
void onSignal(int) {}

// The worker process: one trial, messages into its log, then _exit (robot
// threads that did not answer a watchdog cannot be joined).
[[noreturn]] void workerMain(const ForkJob& job, int t, bool private_shm) {
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  const std::string log = job.logFile(t);
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  int code = 0;
  try {
    if (private_shm) {
      const pid_t parent = getppid();
      const std::string err = enterPrivateShm();
      if (!err.empty()) throw BatchError("a private /dev/shm for the trial: " + err);
      // New credentials may clear the parent-death signal: set it again
      // (and end if the batch died meanwhile).
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(1);
    }
    job.run(t);
  } catch (const ConfigError& ex) {
    std::fprintf(stderr, "%s\n", ex.what());
    code = 2;
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "%s\n", ex.what());
    code = 1;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  if (code == 0) unlink(log.c_str());
  bridge::cleanup::removeAll();
  _exit(code);
}

// A worker ended: a finished trial is handed to the job, a failed one
// reported with the end of its log; an interrupted one leaves no log.
void collect(ForkJob& job, int t, int status, double peak_mb, bool stopping, ForkRun& run) {
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && job.done(t)) {
    job.finished(t, peak_mb);
    ++run.ran;
  } else if (stopping) {
    unlink(job.logFile(t).c_str());  // interrupted, not failed
  } else {
    const std::string why = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                                : "exit code " + std::to_string(WEXITSTATUS(status));
    job.failed(t, why + ": " + fileTail(job.logFile(t), 600) + " (log: " + job.logFile(t) + ")");
    ++run.failed;
  }
}

}  // namespace

ForkRun runForked(ForkJob& job, const std::vector<int>& todo, int jobs, bool private_shm) {
  bool stop = false;
  sigset_t stops;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  // SIGINT, SIGTERM and SIGCHLD stay blocked while the pool runs and are
  // taken with sigwaitinfo: a stop that arrives at any moment -- also just
  // after a check and before the wait -- is pending, and ends the wait at
  // once (a handler's flag set between the check and wait4 waited for a
  // worker to end). A no-op handler keeps an ignored SIGINT (a background
  // job's) from being discarded, as the pool's handler always did.
  sigset_t waited, old_mask;
  sigemptyset(&waited);
  sigaddset(&waited, SIGINT);
  sigaddset(&waited, SIGTERM);
  sigaddset(&waited, SIGCHLD);
  sigprocmask(SIG_BLOCK, &waited, &old_mask);
  struct sigaction sa {}, old_int{}, old_term{}, old_chld{};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  sigaction(SIGCHLD, &sa, &old_chld);  // not SIG_IGN: children must stay waitable
  // Back as they were: a stop still pending taken first (then the mask, so
  // a later signal meets the no-op handler, then the handlers).
  auto restore = [&] {
    const timespec zero{0, 0};
    while (sigtimedwait(&stops, nullptr, &zero) > 0) stop = true;
    sigprocmask(SIG_SETMASK, &old_mask, nullptr);
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    sigaction(SIGCHLD, &old_chld, nullptr);
  };
  ForkRun run;
  const auto wall0 = std::chrono::steady_clock::now();  // wall clock: reporting only
  std::map<pid_t, int> running;
  // A stop signal taken (by sigwaitinfo or the poll): no more launches, and
  // the running workers get it too (a signal to us alone: pass it on).
  auto stopped = [&] {
    stop = true;
    for (const auto& [p, t] : running) kill(p, SIGTERM);
  };
  // One already pending: taken without waiting.
  auto poll = [&] {
    const timespec zero{0, 0};
    while (sigtimedwait(&stops, nullptr, &zero) > 0) stopped();
  };
  try {
    size_t next = 0;
    while ((next < todo.size() && !stop) || !running.empty()) {
      poll();
      while (!stop && next < todo.size() && static_cast<int>(running.size()) < jobs) {
        const int t = todo[next++];
        const pid_t parent = getpid();
        const pid_t pid = fork();
        if (pid < 0) throw BatchError(std::string("fork: ") + std::strerror(errno));
        if (pid == 0) {
          // The batch killed (kill -9 included): the worker goes too, and with
          // it the programs it launched (their own PR_SET_PDEATHSIG,
          // ProgramProcess.cpp). A batch that died before the prctl: we are
          // already an orphan, so end now.
          prctl(PR_SET_PDEATHSIG, SIGKILL);
          if (getppid() != parent) _exit(1);
          // The worker's signals: SIGINT and SIGTERM end it (set before
          // they are unblocked: a stop the pool passed on while they were
          // blocked here is pending, and must not meet the pool's no-op
          // handler), SIGCHLD as the batch had it (the no-op handler would
          // interrupt the worker's own waits).
          signal(SIGINT, SIG_DFL);
          signal(SIGTERM, SIG_DFL);
          sigaction(SIGCHLD, &old_chld, nullptr);
          sigprocmask(SIG_SETMASK, &old_mask, nullptr);
          workerMain(job, t, private_shm);
        }
        running[pid] = t;
        poll();
      }
      // Every worker that has ended, without blocking.
      for (;;) {
        int status = 0;
        rusage usage{};  // the trial process's own: its peak resident memory
        const pid_t pid = wait4(-1, &status, WNOHANG, &usage);
        if (pid == 0 || (pid < 0 && errno == ECHILD)) break;
        if (pid < 0) {
          if (errno == EINTR) continue;
          throw BatchError(std::string("waitpid: ") + std::strerror(errno));
        }
        auto it = running.find(pid);
        if (it == running.end()) continue;  // not ours
        const int t = it->second;
        running.erase(it);
        const double peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB -> MB
        run.peak_mb = std::max(run.peak_mb, peak_mb);
        collect(job, t, status, peak_mb, stop, run);
      }
      if (running.empty() && (stop || next >= todo.size())) break;
      if (static_cast<int>(running.size()) < jobs && !stop && next < todo.size()) continue;  // launch more
      job.waiting();
      siginfo_t info{};
      const int sig = sigwaitinfo(&waited, &info);  // a worker's end or a stop, whichever comes first
      if (sig == SIGINT || sig == SIGTERM) stopped();
    }
  } catch (...) {
    restore();
    throw;
  }
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  restore();
  run.interrupted = stop;
  return run;
}

}  // namespace simswift::experiment
