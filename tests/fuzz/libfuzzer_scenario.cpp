// libFuzzer target for the scenario loader (clang, -DSIMSWIFT_LIBFUZZER=ON; see
// docs/testing.md, "Fuzzing the loaders"). Any crash, hang or ErrorWithoutFile is a finding.
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>

#include "FuzzCases.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simswift::fuzz;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const CaseResult r = runCase(Loader::Scenario, text);
  if (r.outcome == Outcome::ErrorWithoutFile) {
    std::fprintf(stderr, "error without file:line: %s\n", r.message.c_str());
    std::abort();
  }
  return 0;
}
