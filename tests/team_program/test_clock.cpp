// A team's unchanged program meets the run's simulated time (issue 44 item
// 1, docs/shim.md): the clock probe (clock_probe.c, public Linux facts only)
// launched as a V6 robot, under the shim simswift preloads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "sim/programs/Errors.hpp"
#include "sim/runner/Runner.hpp"

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

// The probe launched as robot t<team>p1 on its own socket for `ticks` LoLA
// cycles (12 ms), waiting in `kinds`.
ProbeRun runProbe(int team, int ticks, const std::string& kinds, const std::string& exe = kProbe) {
  const std::string socket = "/tmp/simswift-test-clock-" + std::to_string(::getpid()) + "-" + std::to_string(team) + ".sock";
  std::ostringstream y;
  y << "duration: " << ticks * 0.012 << "\nseed: 5\nattach_timeout: 20\nrobots:\n"
    << "  - {team: " << team << ", player: 1, x: -1.0, y: 0.5, lola: {socket: " << socket
    << "}, program: {command: [\"" << exe << "\", \"{socket}\", \"" << ticks << "\", \"" << kinds << "\"]}}\n";
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
    // Faster than real time (wall clock; the machine may be loaded).
    EXPECT_GT(run.stats.real_time_factor, 1.0);
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
