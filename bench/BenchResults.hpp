// Shared by the benchmark programs: print a figure and append it to the
// results file named in docs/benchmarks.md ("name value unit" per line).
#pragma once

#include <cstdio>
#include <string>

namespace simswift::bench {

inline void report(const std::string& name, double value, const std::string& unit,
                   const char* path = SIMSWIFT_BENCH_RESULTS) {
  std::printf("%-48s %12.2f %s\n", name.c_str(), value, unit.c_str());
  std::fflush(stdout);
  if (FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s %.4f %s\n", name.c_str(), value, unit.c_str());
    std::fclose(f);
  }
}

}  // namespace simswift::bench
