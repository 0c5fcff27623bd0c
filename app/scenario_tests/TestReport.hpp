// What a scenario-test run says: the console summary, summary.csv, the
// Markdown report and its pass-rate figure (gnuplot, as the experiment's
// figures). Everything but wallClockMarkdown is a function of the results.
#pragma once

#include <string>
#include <vector>

#include "app/scenario_tests/Summary.hpp"
#include "app/scenario_tests/TestBatch.hpp"

namespace simswift::scenario_tests {

// "3/10 passed (95 % interval 11-60 %), required 90 %: fails" (+ the
// regression and its p-values).
std::string verdictLine(const TestSummary& s);
// The failing seeds, one line each: run, seed, first failure, replay command.
std::string failureText(const TestFile& f, const TestOptions& opt, const TestSummary& s);
// stdout at the end: one line per test and the failing seeds.
std::string consoleSummary(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests);
std::string summaryCsv(const std::vector<TestSummary>& tests, bool baseline);
std::string reportMarkdown(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests,
                           bool figure);
extern const char* const kTestWallClockHeading;
std::string wallClockMarkdown(const std::vector<TestSummary>& tests, double batch_wall_s);
// DIR/pass_rates.dat, .gp and .png; false with *message if gnuplot is missing or fails.
bool plotPassRates(const std::vector<TestSummary>& tests, const std::string& dir, std::string* message);

}  // namespace simswift::scenario_tests
