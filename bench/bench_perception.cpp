// Perception benchmark: the real-time factor of 1, 3 and 10
// robots walking with the whole robot program (Motion; Perception at 30 Hz
// with the vision adapter, localisation, ball tracker, team modules), wall
// clock and CPU time of this process, and the localisation error (mean,
// 95th percentile) over a 60 s walk with noise on.
//
//   bench_perception [--seeds N] [--threads inline|named] [--robots LIST]
//     --seeds    seeds 1..N (default 5)
//     --threads  the programs' steps on the simulator's thread (inline, the
//                default, as the experiment runs them) or on named threads
//     --robots   comma-separated robot counts to time (default 1,3,10)
//
// The walk: a square of 6 s forward at 250 mm/s and 3 s turning at 0.5 rad/s,
// repeated. Localisation starts from the own half (no game state), so the
// error figures skip the first 5 s (convergence) and sample every 100 ms.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <time.h>

#include "BenchResults.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

namespace {

namespace sb = simswift::bench;
using simswift::runner::Runner;
using simswift::runner::Scenario;

std::string walkActions() {
  std::string a = "[";
  for (int k = 0; k < 8; ++k) {
    const double t = 1.0 + 9.0 * k;
    a += (k ? ", " : "") + std::string("{t: ") + std::to_string(t) + ", action: walk, forward: 250}, {t: " +
         std::to_string(t + 6) + ", action: walk, turn: 0.5}";
  }
  return a + "]";
}

// Up to 10 robots: team 0 (players 1-5) on its own half, team 1 (players
// 1-5) mirrored on the other, all walking the same square.
std::string scenario(int robots, uint64_t seed, double duration) {
  const double xs[5] = {-3.5, -1.5, -3.5, -1.0, -2.5}, ys[5] = {-1.5, 0.5, 1.5, -2.5, 2.7};
  std::string s = "duration: " + std::to_string(duration) + "\nseed: " + std::to_string(seed) +
                  "\nnoise: on\nrobots:\n";
  for (int i = 0; i < robots; ++i) {
    const int team = i / 5, k = i % 5;
    const double side = team == 0 ? 1.0 : -1.0;
    s += "  - {team: " + std::to_string(team) + ", player: " + std::to_string(k + 1) +
         ", x: " + std::to_string(side * xs[k]) + ", y: " + std::to_string(side * ys[k]) +
         ", theta: " + (team == 0 ? "0" : "3.14159") + ", actions: " + walkActions() + "}\n";
  }
  return s;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

agent::program::Threading g_threading = agent::program::Threading::Inline;

// Wall and CPU (this process, all threads) seconds of `seconds` simulated.
void timeRun(int robots, uint64_t seed, double seconds, double* wall, double* cpu) {
  Runner r(Scenario::parse(scenario(robots, seed, seconds), "bench_perception"));
  r.programs().setThreading(g_threading);
  r.start();
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = cpuSeconds();
  const int64_t n = static_cast<int64_t>(std::lround(seconds / 0.01));
  for (int64_t i = 0; i < n; ++i) r.tick();
  *cpu = cpuSeconds() - c0;
  *wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  int seeds = 5;
  std::vector<int> counts = {1, 3, 10};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) {
      seeds = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      const std::string t = argv[++i];
      if (t != "inline" && t != "named") {
        std::fprintf(stderr, "bench_perception: --threads inline|named\n");
        return 2;
      }
      g_threading = t == "inline" ? agent::program::Threading::Inline : agent::program::Threading::Named;
    } else if (!std::strcmp(argv[i], "--robots") && i + 1 < argc) {
      counts.clear();
      for (const char* p = argv[++i]; *p;) {
        const int n = std::atoi(p);
        if (n < 1 || n > 10) {
          std::fprintf(stderr, "bench_perception: --robots: counts in 1..10\n");
          return 2;
        }
        counts.push_back(n);
        while (*p && *p != ',') ++p;
        if (*p) ++p;
      }
    } else {
      std::fprintf(stderr, "usage: bench_perception [--seeds N] [--threads inline|named] [--robots 1,3,10]\n");
      return 2;
    }
  }
  const std::string mode = g_threading == agent::program::Threading::Inline ? "" : ".named_threads";

  // Real-time factor (20 s of walking per seed, summed; 10 robots: 10 s).
  for (int robots : counts) {
    const double seconds = robots >= 10 ? 10.0 : 20.0;
    double sim = 0, wall = 0, cpu = 0;
    for (int s = 1; s <= seeds; ++s) {
      double w, c;
      timeRun(robots, s, seconds, &w, &c);
      sim += seconds;
      wall += w;
      cpu += c;
    }
    const std::string name =
        "perception.walking_" + std::to_string(robots) + "_robot" + (robots > 1 ? "s" : "") + mode;
    sb::report(name + ".real_time_factor", sim / wall, "x");
    sb::report(name + ".real_time_factor_cpu", sim / cpu, "x");
  }

  // Localisation error over a 60 s walk (team 0: the field frame is the world's).
  std::vector<double> pos, head, seed_means;
  int frames_seen = 0;
  for (int s = 1; s <= seeds; ++s) {
    Runner r(Scenario::parse(scenario(1, s, 60.0), "bench_perception"));
    r.programs().setThreading(g_threading);
    r.start();
    std::vector<double> mine;
    for (int64_t i = 1; i <= 6000; ++i) {
      r.tick();
      if (i < 500 || i % 10 != 0) continue;
      const auto est = r.programs().program(0)->board().localisation.read();
      const auto t = r.world().robot(0).torsoPose();
      const double e = std::hypot(est.pose.x - 1000 * t.x, est.pose.y - 1000 * t.y);
      const double dh = t.heading - est.pose.theta;
      pos.push_back(e);
      mine.push_back(e);
      head.push_back(std::fabs(std::atan2(std::sin(dh), std::cos(dh))));
    }
    frames_seen += r.programs().program(0)->board().vision.read().num_features;
    double m = 0;
    for (double e : mine) m += e;
    seed_means.push_back(m / mine.size());
  }
  double mean = 0, mean_h = 0;
  for (double e : pos) mean += e;
  for (double e : head) mean_h += e;
  mean /= pos.size();
  mean_h /= head.size();
  std::sort(seed_means.begin(), seed_means.end());
  sb::report("perception.localisation_60s.error_mean", mean, "mm");
  sb::report("perception.localisation_60s.error_p95", percentile(pos, 0.95), "mm");
  sb::report("perception.localisation_60s.heading_error_mean", mean_h * 180 / M_PI, "deg");
  sb::report("perception.localisation_60s.heading_error_p95", percentile(head, 0.95) * 180 / M_PI, "deg");
  sb::report("perception.localisation_60s.seed_mean_min", seed_means.front(), "mm");
  sb::report("perception.localisation_60s.seed_mean_max", seed_means.back(), "mm");
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  sb::report("perception.peak_memory", static_cast<double>(ru.ru_maxrss) / 1024.0, "MB");  // KiB -> MB
  if (frames_seen == 0)
    std::printf("note: the frames carried no field features (no vision oracle in this build): "
                "the localisation figures are dead reckoning from the own-half prior\n");
  return 0;
}
