// Recording benchmark (docs/recording.md): what recording a run as MCAP
// costs. 1 and 3 robots walking with the builtin program (Motion, and
// Perception at 30 Hz with team messages), inline; each run timed in CPU
// seconds of this process without a recorder and with one at the default
// rate (20 Hz), interleaved, the fastest of --repeats each; then the
// recording's size per robot per simulated minute.
//
//   bench_record [--seconds S] [--repeats N]     (defaults 20 s, 3)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include <time.h>
#include <unistd.h>

#include "BenchResults.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/runner/Runner.hpp"

namespace {

namespace sb = simswift::bench;
using simswift::runner::Runner;
using simswift::runner::Scenario;

// Robots of team 19 walking squares on their own half (6 s forward at
// 250 mm/s, 3 s turning at 0.5 rad/s), the ball on the centre spot.
std::string scenario(int robots, double seconds) {
  std::string actions = "[";
  for (int k = 0; k * 9.0 < seconds; ++k) {
    const double t = 1.0 + 9.0 * k;
    actions += (k ? ", " : "") + std::string("{t: ") + std::to_string(t) + ", action: walk, forward: 250}, {t: " +
               std::to_string(t + 6) + ", action: walk, turn: 0.5}";
  }
  actions += "]";
  const double xs[3] = {-3.5, -1.5, -3.5}, ys[3] = {-1.5, 0.5, 1.5};
  std::string s = "duration: " + std::to_string(seconds) + "\nseed: 1\nnoise: on\nrobots:\n";
  for (int i = 0; i < robots; ++i)
    s += "  - {team: 19, player: " + std::to_string(i + 1) + ", x: " + std::to_string(xs[i]) +
         ", y: " + std::to_string(ys[i]) + ", theta: 0, actions: " + actions + "}\n";
  return s;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// CPU seconds of the run's ticks (the start not counted); recorded to
// `path` unless it is empty. Returns the file's size in *bytes.
double timeRun(int robots, double seconds, const std::string& path, uintmax_t* bytes) {
  Runner r(Scenario::parse(scenario(robots, seconds), "bench_record"));
  r.programs().setThreading(agent::program::Threading::Inline);
  r.start();
  std::unique_ptr<simswift::record::Recorder> rec;
  if (!path.empty()) {
    rec = std::make_unique<simswift::record::Recorder>(path);
    r.addObserver(rec.get());
  }
  const double c0 = cpuSeconds();
  const int64_t n = r.world().ticksIn(seconds);
  for (int64_t i = 0; i < n; ++i) r.tick();
  if (rec) rec->finish();
  const double cpu = cpuSeconds() - c0;
  if (bytes) *bytes = path.empty() ? 0 : std::filesystem::file_size(path);
  return cpu;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 20;
  int repeats = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--seconds")) seconds = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeats")) repeats = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: bench_record [--seconds S] [--repeats N]\n");
      return 2;
    }
  }
  if (!(seconds >= 1 && seconds <= 600) || repeats < 1 || repeats > 20) {
    std::fprintf(stderr, "bench_record: --seconds in [1, 600], --repeats in [1, 20]\n");
    return 2;
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / ("bench_record_" + std::to_string(::getpid()) + ".mcap")).string();
  std::printf("recording at %g Hz, %g simulated s, fastest of %d interleaved runs, CPU time of this process\n",
              simswift::record::RecordOptions::kDefaultRateHz, seconds, repeats);
  for (const int robots : {1, 3}) {
    double plain = 1e30, recorded = 1e30;
    uintmax_t bytes = 0;
    for (int k = 0; k < repeats; ++k) {
      plain = std::min(plain, timeRun(robots, seconds, "", nullptr));
      recorded = std::min(recorded, timeRun(robots, seconds, path, &bytes));
    }
    const std::string n = std::to_string(robots) + (robots == 1 ? " robot" : " robots");
    sb::report("record: " + n + " real-time factor without", seconds / plain, "x");
    sb::report("record: " + n + " real-time factor recorded", seconds / recorded, "x");
    sb::report("record: " + n + " speed lost to recording", 100.0 * (1.0 - plain / recorded), "%");
    sb::report("record: " + n + " size per robot per simulated minute",
               static_cast<double>(bytes) / robots / (seconds / 60.0) / 1e6, "MB");
  }
  std::filesystem::remove(path);
  return 0;
}
