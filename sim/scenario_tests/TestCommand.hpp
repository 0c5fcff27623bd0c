// `simswift test ...`: the command line of the scenario tests
// (app/simswift.cpp hands over argv after "test"; docs/testing.md).
#pragma once

namespace simswift::scenario_tests {

extern const char* kTestUsage;

// argv[0] is "test". Returns the exit code: 0 every test passes and none
// regressed; 1 a test fails, is undecided or regressed, or a run could not
// run; 2 bad command line or test file; 130 interrupted.
int testMain(int argc, char** argv);

}  // namespace simswift::scenario_tests
