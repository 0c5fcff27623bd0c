// One fuzz case per loader, shared by the seeded mutation fuzzer
// (fuzz_loaders.cpp, in CI) and the libFuzzer targets (libfuzzer_*.cpp, by
// hand). A case feeds text to a loader exactly as a user's file would reach
// it; an accepted input is then built into a World and stepped a few ticks
// (ODE aborted on values the loaders once accepted). The rules:
//   - refusal must be ModelError / ConfigError starting "<source>:<line>: ";
//   - anything else thrown is an "error without a file" (a finding);
//   - a crash or a hang is a finding by itself.
#pragma once

#include <string>

namespace simswift::fuzz {

enum class Loader { Urdf, Field, Scenario };
const char* loaderName(Loader l);
const char* sourceName(Loader l);  // the file name the case pretends to be

enum class Outcome { Accepted, Refused, ErrorWithoutFile };

struct CaseResult {
  Outcome outcome = Outcome::Accepted;
  std::string message;  // the error, if any
};

// Runs one input through loader `l` (and, if accepted, a few World ticks).
CaseResult runCase(Loader l, const std::string& text);

// The shipped inputs the mutations start from.
std::string seedText(Loader l);

}  // namespace simswift::fuzz
