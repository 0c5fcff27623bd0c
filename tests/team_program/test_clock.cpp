// A team's unchanged program meets the run's simulated time (issue 44 item
// 1, docs/shim.md): the clock probe (clock_probe.c, public Linux facts only)
// launched as a V6 robot, under the shim simswift preloads.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "sim/programs/Errors.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/Attach.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;

namespace {

const std::string kProbe = std::string(SIMSWIFT_BINARY_DIR) + "/clock-probe";

// Every kind of timed wait the probe knows; each ends on its own cycle.
const char* const kWaits =
    "nanosleep,clock_nanosleep,clock_nanosleep_abs,clock_nanosleep_abs_realtime,usleep,sleep,"
    "cond_timedwait,cond_monotonic,cond_clockwait,sem_timedwait,sem_clockwait,"
    "poll,poll_nofds,ppoll,select,select_nofds,pselect,epoll_wait,epoll_pwait,timerfd,syscall_nanosleep";
constexpr size_t kNumWaits = 21;

struct ProbeRun {
  simswift::runner::RunStats stats;
  uint64_t hash = 0;
  std::vector<std::string> log;
};

std::string logsFolder(int team) {
  return "/tmp/simswift-test-clock-" + std::to_string(::getpid()) + "-" + std::to_string(team);
}

enum class Body { V6, V5 };

// The probe launched as robot t<team>p1 for `ticks` cycles, waiting in
// `kinds`: a V6 on its own LoLA socket (12 ms), or a V5 on libagent's block
// (10 ms, the 2017 release's names: `{memory}`); `before`: YAML list items
// put before it in the command (a debugger).
ProbeRun runProbe(int team, int ticks, const std::string& kinds, const std::string& exe = kProbe,
                  const std::string& before = "", Body body = Body::V6) {
  const std::string socket = "/tmp/simswift-test-clock-" + std::to_string(::getpid()) + "-" + std::to_string(team) + ".sock";
  std::ostringstream y;
  y << "duration: " << ticks * (body == Body::V6 ? 0.012 : 0.010) << "\nseed: 5\nattach_timeout: 20\nrobots:\n"
    << "  - {team: " << team << ", player: 1, x: -1.0, y: 0.5, "
    << (body == Body::V6 ? "lola: {socket: " + socket + "}, " : std::string("libagent: {release: 2017}, "))
    << "program: {command: [" << before << "\"" << exe << "\", \"" << (body == Body::V6 ? "{socket}" : "{memory}")
    << "\", \"" << ticks << "\", \"" << kinds << "\"]}}\n";
  Scenario sc = Scenario::parse(y.str(), std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/v6_test.yaml");
  sc.program_logs = logsFolder(team);
  ProbeRun out;
  {
    Runner r(sc);
    simswift::runner::RunOptions o;
    o.progress = false;
    out.stats = r.run(o);
    out.hash = r.world().stateHash();
  }
  std::ifstream in(sc.program_logs + "/t" + std::to_string(team) + "p1.log");
  for (std::string line; std::getline(in, line);) out.log.push_back(line);
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

// Lines starting with `prefix`.
std::vector<std::string> linesOf(const std::vector<std::string>& log, const std::string& prefix) {
  std::vector<std::string> out;
  for (const std::string& l : log)
    if (l.rfind(prefix, 0) == 0) out.push_back(l);
  return out;
}

}  // namespace

// Every clock the probe reads advances exactly 12 ms (to the nanosecond;
// gettimeofday to the microsecond) per LoLA packet, each timed wait ends at
// the first cycle at or after the time it asked for, two runs give the same
// state hash and the same digest of everything the probe read, and the run
// is faster than real time.
TEST(ClockV6, ClocksStepOneCycleAndWaitsEndOnTime) {
  const int ticks = 210;  // 2.52 s: the 1 s sleep (85 cycles) and 20 waits of 3 to 4 cycles, with hand-overs
  ProbeRun runs[2] = {runProbe(81, ticks, kWaits), runProbe(81, ticks, kWaits)};
  for (const ProbeRun& run : runs) {
    const std::string log = joined(run.log);
    EXPECT_EQ(run.stats.ticks, ticks);
    const std::vector<std::string> clocks = linesOf(run.log, "clock ");
    EXPECT_EQ(clocks.size(), 8u) << log;  // six clock ids, gettimeofday, the raw syscall
    for (const std::string& l : clocks) EXPECT_NE(l.find(" bad=0"), std::string::npos) << l;
    const std::vector<std::string> waits = linesOf(run.log, "wait ");
    EXPECT_EQ(waits.size(), kNumWaits) << log;
    for (const std::string& l : waits) EXPECT_NE(l.find(" ok"), std::string::npos) << l;
    EXPECT_EQ(linesOf(run.log, "digest ").size(), 1u) << log;
    // Faster than real time (wall clock; the machine may be loaded): the
    // Release build's claim, not an instrumented build's.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    EXPECT_GT(run.stats.real_time_factor, 1.0);
#endif
  }
  EXPECT_EQ(runs[0].hash, runs[1].hash);
  EXPECT_EQ(linesOf(runs[0].log, "digest "), linesOf(runs[1].log, "digest "));
}

// The same probe launched as a V5 robot (libagent's block and semaphore,
// the 2017 release): every clock advances exactly 10 ms per libagent cycle,
// every timed wait ends at the first cycle at or after its time, and two
// runs give the same state hash and digest. Before, only the V6 (LoLA) body
// was checked (the probe spoke LoLA only).
TEST(ClockV5, ClocksStepOneCycleAndWaitsEndOnTime) {
  const int ticks = 250;  // 2.5 s: the 1 s sleep (100 cycles) and 20 waits of 3 cycles, with hand-overs
  ProbeRun runs[2] = {runProbe(85, ticks, kWaits, kProbe, "", Body::V5),
                      runProbe(85, ticks, kWaits, kProbe, "", Body::V5)};
  for (const ProbeRun& run : runs) {
    const std::string log = joined(run.log);
    EXPECT_EQ(run.stats.ticks, ticks);
    const std::vector<std::string> clocks = linesOf(run.log, "clock ");
    EXPECT_EQ(clocks.size(), 8u) << log;
    for (const std::string& l : clocks) {
      EXPECT_NE(l.find(" steps=" + std::to_string(ticks - 1) + " "), std::string::npos) << l;
      EXPECT_NE(l.find(" bad=0"), std::string::npos) << l;
    }
    const std::vector<std::string> waits = linesOf(run.log, "wait ");
    EXPECT_EQ(waits.size(), kNumWaits) << log;
    for (const std::string& l : waits) EXPECT_NE(l.find(" ok"), std::string::npos) << l;
    // A 30 ms wait from a cycle's time ends exactly 3 cycles (30 ms) later.
    for (const std::string& l : linesOf(run.log, "wait nanosleep ")) {
      const long long start = std::stoll(l.substr(l.find("start=") + 6)), end = std::stoll(l.substr(l.find("end=") + 4));
      EXPECT_EQ(end - start, 30000000LL) << l;
    }
    EXPECT_EQ(linesOf(run.log, "digest ").size(), 1u) << log;
  }
  EXPECT_EQ(runs[0].hash, runs[1].hash);
  EXPECT_EQ(linesOf(runs[0].log, "digest "), linesOf(runs[1].log, "digest "));
}

#ifdef SIMSWIFT_HAVE_STATIC_PROBE
// A static binary cannot take the shim: refused at launch, naming the
// robot and the program, before anything runs on the wall clock.
TEST(ClockV6, AStaticBinaryIsRefused) {
  try {
    runProbe(82, 10, "nanosleep", std::string(SIMSWIFT_BINARY_DIR) + "/clock-probe-static");
    FAIL() << "a static program ran";
  } catch (const simswift::programs::ProgramError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("robot t82p1"), std::string::npos) << m;
    EXPECT_NE(m.find("clock-probe-static"), std::string::npos) << m;
    EXPECT_NE(m.find("statically linked"), std::string::npos) << m;
  }
}
#endif

// The seccomp filter stays over exec, a signal handler does not: a program
// exec'd by a launched wrapper script runs under its parent's filter, and
// a raw clock call before the shim's constructor (the probe's
// .preinit_array, where ASan reads the clock) found no handler: SIGSYS
// killed it (seen with the ASan build of simswift-agent under `sh -c`). The
// early handler (LD_AUDIT, shim/early/Early.cpp) answers it from the
// machine's clock; from its constructor on the program reads the run's
// time as when launched directly: the same digest and state hash.
TEST(ClockV6, AProgramExecdByAWrapperSurvivesARawClockCallBeforeTheShimLoads) {
  const int ticks = 40;
  const ProbeRun direct = runProbe(84, ticks, "nanosleep");
  const ProbeRun wrapped = runProbe(84, ticks, "nanosleep", kProbe, "sh, -c, 'exec \"$0\" \"$@\"', ");
  EXPECT_EQ(linesOf(wrapped.log, "preinit raw clock_gettime rc=0").size(), 1u) << joined(wrapped.log);
  const std::vector<std::string> digest = linesOf(direct.log, "digest ");
  ASSERT_EQ(digest.size(), 1u) << joined(direct.log);
  EXPECT_EQ(linesOf(wrapped.log, "digest "), digest) << joined(wrapped.log);
  EXPECT_EQ(wrapped.hash, direct.hash);
}

// gdb (issue 44 item 5): the program under gdb, launched as the robot's
// command, sees the same simulated time as without it (the same digest of
// every reading and wait), while gdb itself keeps the wall clock (the shim
// is inert in it, docs/shim.md). Skipped where gdb is not installed.
TEST(ClockV6, UnderGdbTheProgramSeesTheSameTime) {
  if (::access("/usr/bin/gdb", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/gdb";
  const int ticks = 40;
  const std::string kinds = "nanosleep,cond_timedwait,poll";
  const ProbeRun plain = runProbe(83, ticks, kinds);
  // gdb prints its own clock (its Python's time.time()) before it runs the probe.
  const ProbeRun gdb = runProbe(83, ticks, kinds, kProbe,
                                "/usr/bin/gdb, -batch, -nx, -ex, \"python print('gdb-clock', int(__import__('time').time()))\", "
                                "-ex, \"handle SIGSYS nostop noprint pass\", -ex, run, --args, ");
  const std::vector<std::string> clock = linesOf(gdb.log, "gdb-clock ");
  ASSERT_EQ(clock.size(), 1u) << joined(gdb.log);
  EXPECT_NEAR(std::stod(clock[0].substr(10)), static_cast<double>(::time(nullptr)), 600) << "gdb keeps the wall clock";
  const std::vector<std::string> digest = linesOf(plain.log, "digest ");
  ASSERT_EQ(digest.size(), 1u) << joined(plain.log);
  EXPECT_EQ(linesOf(gdb.log, "digest "), digest) << joined(gdb.log);
  EXPECT_EQ(linesOf(gdb.log, "wait "), linesOf(plain.log, "wait ")) << joined(gdb.log);
  EXPECT_EQ(gdb.hash, plain.hash);
}

// `simswift attach` (issue 44 items 1 and 5): the probe started by hand on a
// robot whose program is external, directly and under gdb, reads what the
// launched probe reads (the same digest, the same waits, the same hash).
namespace {

// The probe (or `before` + probe) started with `simswift attach --team
// <team> --player 1` while the run of an external robot runs; its output.
ProbeRun runAttached(int team, int ticks, const std::string& kinds, const std::vector<std::string>& before) {
  std::ostringstream y;
  y << "duration: " << ticks * 0.012 << "\nseed: 5\nattach_timeout: 20\nrobots:\n"
    << "  - {team: " << team << ", player: 1, x: -1.0, y: 0.5, lola: {}, program: external}\n";
  Scenario sc = Scenario::parse(y.str(), std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/v6_test.yaml");
  sc.program_logs = logsFolder(team);
  const std::string log = sc.program_logs + "-attached.log";
  ProbeRun out;
  pid_t pid = -1;
  {
    Runner r(sc);
    r.start();  // the socket and the clock page exist from here
    std::vector<std::string> command = before;
    for (const std::string& a : {kProbe, std::string("-"), std::to_string(ticks), kinds}) command.push_back(a);
    pid = simswift::testing::startAttach(team, 1, command, log);
    simswift::runner::RunOptions o;
    o.progress = false;
    out.stats = r.run(o);
    out.hash = r.world().stateHash();
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) out.log.push_back(line);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << joined(out.log);
  return out;
}

}  // namespace

TEST(ClockV6, AttachedAndAttachedUnderGdbReadTheLaunchedView) {
  const int ticks = 40;
  const std::string kinds = "nanosleep,cond_timedwait,poll";
  const ProbeRun launched = runProbe(84, ticks, kinds);
  const std::vector<std::string> digest = linesOf(launched.log, "digest ");
  ASSERT_EQ(digest.size(), 1u) << joined(launched.log);
  const ProbeRun attached = runAttached(84, ticks, kinds, {});
  EXPECT_EQ(linesOf(attached.log, "digest "), digest) << joined(attached.log);
  EXPECT_EQ(attached.hash, launched.hash);
  if (::access("/usr/bin/gdb", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/gdb";
  const ProbeRun gdb = runAttached(84, ticks, kinds,
                                   {"/usr/bin/gdb", "-batch", "-nx", "-ex", "handle SIGSYS nostop noprint pass", "-ex",
                                    "run", "--args"});
  EXPECT_EQ(linesOf(gdb.log, "digest "), digest) << joined(gdb.log);
  EXPECT_EQ(linesOf(gdb.log, "wait "), linesOf(launched.log, "wait ")) << joined(gdb.log);
  EXPECT_EQ(gdb.hash, launched.hash);
}
