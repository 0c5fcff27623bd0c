// The JUnit XML of a scenario-test run, in the form GitLab and Jenkins read
// (the de-facto schema of Ant's JUnit report: <testsuites> holding one
// <testsuite> with one <testcase> per scenario test). A test that does not
// pass, or regressed, has a <failure> whose type is its verdict ("fails",
// "undecided", "regression"), whose message says the pass count, the
// interval and the required rate, and whose text lists the failing seeds
// with each one's first failure and replay command. `time` is wall-clock
// seconds (the one part that differs between identical runs).
#pragma once

#include <string>
#include <vector>

#include "app/scenario_tests/Summary.hpp"
#include "app/scenario_tests/TestBatch.hpp"

namespace simswift::scenario_tests {

std::string junitXml(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests);

// &, <, >, " and ' as entities; control characters other than tab and
// newline (not allowed in XML 1.0) as '?'.
std::string xmlEscape(const std::string& s);

}  // namespace simswift::scenario_tests
