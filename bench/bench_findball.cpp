// Time to find the ball in physics, noise on (thesis 5.1's whole-field
// search): table 5.1's robots (1: robot 2; 3: robots 2, 3, 4) running the
// 2016 FindBall or the 2017 ball searching component, the ball at table
// 5.2's positions 1-5, 180 s limit, found = a robot sees the ball and is
// within 300 mm of it by ground truth (harness/FindBallHarness.hpp).
//
//   bench_findball [--robots 1|3|both] [--seeds N] [--first-seed S] [--positions 1,2,..]
//
// Seeds 1..5 by default (never the tests' 301.. nor the tuning seed 11).
// Prints one line per run and a table (mean [min, max] over the seeds found,
// with the count found); appends "findball.<kind>.r<N>.p<P> mean s" and
// ".found" lines to bench-results.txt.
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "BenchResults.hpp"
#include "harness/FindBallHarness.hpp"

namespace fh = findball_harness;

int main(int argc, char** argv) {
  std::vector<int> team_sizes{1, 3};
  int seeds = 5, first_seed = 1;
  std::vector<int> positions{1, 2, 3, 4, 5};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bench_findball: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--robots") {
      const std::string v = next();
      team_sizes = v == "both" ? std::vector<int>{1, 3} : std::vector<int>{std::atoi(v.c_str())};
    } else if (a == "--seeds") {
      seeds = std::atoi(next().c_str());
    } else if (a == "--first-seed") {
      first_seed = std::atoi(next().c_str());
    } else if (a == "--positions") {
      positions.clear();
      const std::string v = next();
      for (size_t p = 0; p < v.size(); ++p)
        if (v[p] >= '1' && v[p] <= '5') positions.push_back(v[p] - '0');
    } else {
      std::fprintf(stderr, "bench_findball: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  struct Cell {
    double sum = 0, lo = 1e9, hi = 0;
    int found = 0;
  };
  for (int robots : team_sizes) {
    for (const char* kind : {"findball2016", "findball2017"}) {
      std::vector<Cell> cells;
      for (int pos : positions) {
        Cell c;
        for (int s = first_seed; s < first_seed + seeds; ++s) {
          simswift::runner::Runner r(simswift::runner::Scenario::parse(fh::scenario(robots, kind, pos, s, 180), "bench"));
          r.programs().setThreading(agent::program::Threading::Inline);
          const fh::FindTimes t = fh::timeToFind(r, 180.0);
          std::printf("  %s robots %d position %d seed %d: %s  (falls %d)\n", kind, robots, pos, s,
                      t.truth ? (std::to_string(*t.truth) + " s").c_str() : "not found", r.stats().falls);
          std::fflush(stdout);
          if (t.truth) {
            ++c.found;
            c.sum += *t.truth;
            c.lo = std::min(c.lo, *t.truth);
            c.hi = std::max(c.hi, *t.truth);
          }
        }
        const std::string name = std::string("findball.") + kind + ".r" + std::to_string(robots) + ".p" + std::to_string(pos);
        if (c.found) simswift::bench::report(name + ".mean", c.sum / c.found, "s");
        simswift::bench::report(name + ".found", c.found, "of " + std::to_string(seeds));
        cells.push_back(c);
      }
      std::printf("| %s | %d |", kind, robots);
      for (const Cell& c : cells) {
        if (c.found)
          std::printf(" %.1f [%.1f, %.1f] %d/%d |", c.sum / c.found, c.lo, c.hi, c.found, seeds);
        else
          std::printf(" not found 0/%d |", seeds);
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  return 0;
}
