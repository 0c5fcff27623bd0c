// The speed cost of a launched program's view (issue 44): the reference
// robot program launched as a team's binary would be (`simswift-agent
// --config {config}`: its own process under simswift's init, the shim's
// simulated clock) against the same program builtin (threads of simswift),
// at 1 and 3 robots searching for the ball (findball2017, noise on):
//   launched.builtin.N_robot(s).realtime_factor    builtin, named threads
//   launched.plain.N_robot(s).realtime_factor      launched, the shim and the
//                                                  init, no namespaces (the
//                                                  machine's /tmp and network:
//                                                  SIMSWIFT_MOUNT_NAMESPACE=off,
//                                                  SIMSWIFT_NETWORK_NAMESPACE=off)
//   launched.view.N_robot(s).realtime_factor       launched in its full view:
//                                                  PID, mount and (where the
//                                                  machine gives them) network
//                                                  namespaces, wlan0 read each tick
//   launched.plain|view.N_robot(s).cost_percent   wall time of the launched run
//                                                  over the builtin run, - 100
// Each line says whether the run gave the builtin run's state hash.
//
// Each figure is the best of REPEATS runs, the cases interleaved (the
// machine's load moves between runs; the best is the least disturbed).
//
// Usage: bench_launched [SIM_SECONDS=10] [REPEATS=3] ; figures are printed and appended
// to the results file (bench/BenchResults.hpp). Needs simswift-agent and the
// shim built beside it (the build folder).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "BenchResults.hpp"
#include "sim/programs/MountNamespace.hpp"
#include "sim/programs/RobotNetwork.hpp"
#include "sim/runner/Runner.hpp"

using namespace simswift;

namespace {

enum class Case { Builtin, Plain, View };

struct Result {
  double rtf = 0;
  uint64_t hash = 0;
};

Result run(Case c, int robots, double seconds) {
  const std::string logs = "/tmp/simswift-bench-launched-" + std::to_string(::getpid());
  std::ostringstream y;
  y << "duration: " << seconds << "\nseed: 3\nnoise: on\nball: {x: 3.5, y: -2.0}\nprogram_logs: " << logs
    << "\nrobots:\n";
  const char* poses[] = {"x: -3.0, y: 3.0, theta: -1.5708", "x: -2.0, y: -3.0, theta: 1.5708",
                         "x: 0.5, y: 2.0, theta: -1.5708"};
  for (int r = 0; r < robots; ++r) {
    y << "  - {team: 19, player: " << r + 2 << ", " << poses[r] << ", behaviour: findball2017";
    if (c != Case::Builtin)
      y << ", program: {command: [\"" << SIMSWIFT_BINARY_DIR << "/simswift-agent\", --config, \"{config}\"]}";
    y << "}\n";
  }
  if (c == Case::Plain) {
    ::setenv("SIMSWIFT_MOUNT_NAMESPACE", "off", 1);
    ::setenv("SIMSWIFT_NETWORK_NAMESPACE", "off", 1);
  } else {
    ::unsetenv("SIMSWIFT_MOUNT_NAMESPACE");
    ::unsetenv("SIMSWIFT_NETWORK_NAMESPACE");
  }
  Result out;
  {
    runner::Runner r(runner::Scenario::parse(y.str(), "bench_launched.yaml"));
    runner::RunOptions o;
    o.progress = false;
    const runner::RunStats s = r.run(o);
    out.rtf = s.real_time_factor;
    out.hash = s.hash;
  }
  std::error_code ec;
  std::filesystem::remove_all(logs, ec);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 10.0;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::printf("simswift launched-program benchmark: %.0f simulated s per run, best of %d; namespaces: mount %s, "
              "network %s\n",
              seconds, repeats, programs::mountNamespaceSupport().available ? "yes" : "no",
              programs::robotNetworkSupport().available ? "yes" : "no");
  for (int n : {1, 3}) {
    const std::string robots = std::to_string(n) + "_robot" + (n > 1 ? "s" : "");
    Result best[3];
    for (int k = 0; k < repeats; ++k)
      for (Case c : {Case::Builtin, Case::Plain, Case::View}) {
        const Result r = run(c, n, seconds);
        Result& b = best[static_cast<int>(c)];
        if (k > 0 && r.hash != b.hash) std::printf("  run %d of case %d: another state hash\n", k, static_cast<int>(c));
        if (r.rtf > b.rtf) b = r;
      }
    const Result builtin = best[0];
    bench::report("launched.builtin." + robots + ".realtime_factor", builtin.rtf, "x");
    for (Case c : {Case::Plain, Case::View}) {
      const Result l = best[static_cast<int>(c)];
      const std::string name = std::string("launched.") + (c == Case::Plain ? "plain." : "view.") + robots;
      bench::report(name + ".realtime_factor", l.rtf, "x");
      bench::report(name + ".cost_percent", (builtin.rtf / l.rtf - 1.0) * 100.0, "%");
      std::printf("  %s: state hash %s the builtin run's\n", name.c_str(), l.hash == builtin.hash ? "equals" : "DIFFERS from");
    }
  }
  return 0;
}
