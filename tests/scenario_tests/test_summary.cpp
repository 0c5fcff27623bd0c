// Verdicts from the Wilson interval, the baseline comparison (one-sided
// Fisher and Mann-Whitney, Holm), exit codes.
#include <gtest/gtest.h>

#include <cmath>

#include "app/experiment/Statistics.hpp"
#include "app/scenario_tests/Summary.hpp"

namespace {

using namespace simswift::scenario_tests;
namespace stats = simswift::experiment::stats;

const std::string kSource = std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/tests/t.yaml";

TestFile oneTest(double required) {
  return TestFile::parse("name: t\ntests:\n  - name: a\n    required: " + std::to_string(required) +
                             "\n    scenario: {robots: [{team: 19, player: 2}]}\n    pass: {never: {fallen: any}}\n",
                         kSource);
}

// Runs 0..n-1 of `test`, the first `passed` of them passing; run i's seed
// is seed0 + i (the same seed0 on both sides: paired runs, as the same file
// seed gives; another: independent ones).
std::vector<RunResult> runs(const std::string& test, int n, int passed, double pass_time = 10, double step = 1,
                            uint64_t seed0 = 0) {
  std::vector<RunResult> v;
  for (int i = 0; i < n; ++i) {
    RunResult r;
    r.index = i;
    r.test = test;
    r.run = i;
    r.seed = seed0 + static_cast<uint64_t>(i);
    r.passed = i < passed;
    r.decided_s = pass_time + step * i;
    if (!r.passed) r.failure = "x";
    v.push_back(r);
  }
  return v;
}

TEST(Verdict, FromTheWilsonIntervalAgainstTheRequiredRate) {
  const TestFile f = oneTest(0.75);
  // 12/12: interval 0.757-1 (lower end >= 0.75): passes.
  EXPECT_EQ(summarise(f, runs("a", 12, 12))[0].verdict, TestSummary::Verdict::Passes);
  // 11/12: 0.646-0.985 straddles 0.75: undecided.
  const TestSummary u = summarise(f, runs("a", 12, 11))[0];
  EXPECT_EQ(u.verdict, TestSummary::Verdict::Undecided);
  EXPECT_NEAR(u.lo, 0.646, 0.001);
  EXPECT_EQ(u.failures.size(), 1u);
  // 3/12: upper end 0.53 < 0.75: fails.
  EXPECT_EQ(summarise(f, runs("a", 12, 3))[0].verdict, TestSummary::Verdict::Fails);
  EXPECT_EQ(exitCode(summarise(f, runs("a", 12, 12))), 0);
  EXPECT_EQ(exitCode(summarise(f, runs("a", 12, 11))), 1);
}

TEST(Statistics, OneSidedTestsOnKnownTables) {
  // 0/10 against 10/10: only this table, 1 / C(20, 10).
  EXPECT_NEAR(stats::fisherLess(0, 10, 10, 0), 1.0 / 184756.0, 1e-12);
  EXPECT_DOUBLE_EQ(stats::fisherLess(10, 0, 0, 10), 1.0);
  // Every x above every y, three each: 1 of C(6, 3) = 20 arrangements.
  const stats::MannWhitney m = stats::mannWhitneyGreater({4, 5, 6}, {1, 2, 3});
  EXPECT_TRUE(m.exact);
  EXPECT_NEAR(m.p, 0.05, 1e-12);
  EXPECT_NEAR(stats::mannWhitneyGreater({1, 2, 3}, {4, 5, 6}).p, 1.0, 1e-12);
  // Holm: sorted 0.01, 0.02, 0.04 times 3, 2, 1, kept monotone.
  const std::vector<double> h = stats::holm({0.04, 0.01, 0.02});
  EXPECT_NEAR(h[1], 0.03, 1e-12);
  EXPECT_NEAR(h[2], 0.04, 1e-12);
  EXPECT_NEAR(h[0], 0.04, 1e-12);
}

TEST(Baseline, ALowerRateIsARegressionTheSameRateIsNot) {
  const TestFile f = oneTest(0.5);
  std::vector<TestSummary> weak = summarise(f, runs("a", 10, 2));
  const std::vector<RunResult> base = runs("a", 10, 10, 10, 1, 1000);  // other seeds: independent
  compareWithBaseline(weak, runs("a", 10, 2), base, 0.05);
  ASSERT_TRUE(weak[0].compared);
  EXPECT_TRUE(weak[0].regressed);
  EXPECT_LT(weak[0].p_rate_adj, 0.001);
  EXPECT_EQ(exitCode(weak), 1);
  std::vector<TestSummary> same = summarise(f, runs("a", 10, 9));
  compareWithBaseline(same, runs("a", 10, 9), base, 0.05);
  EXPECT_FALSE(same[0].regressed);
  EXPECT_GT(same[0].p_rate, 0.05);
}

TEST(Baseline, SlowerPassesAreARegression) {
  const TestFile f = oneTest(0.5);
  const std::vector<RunResult> now = runs("a", 10, 10, 30, 1), base = runs("a", 10, 10, 10, 1, 1000);
  std::vector<TestSummary> s = summarise(f, now);
  compareWithBaseline(s, now, base, 0.05);
  EXPECT_TRUE(s[0].time_compared);
  EXPECT_TRUE(s[0].regressed);
  EXPECT_DOUBLE_EQ(s[0].p_rate, 1.0);  // the rate is the same
  EXPECT_LT(s[0].p_time_adj, 0.001);
  // Faster is not a regression.
  std::vector<TestSummary> fast = summarise(f, base);
  compareWithBaseline(fast, base, now, 0.05);
  EXPECT_FALSE(fast[0].regressed);
  EXPECT_EQ(s[0].pairs, 0);  // no seed in common: independent samples
}

// The same seeds on both sides (the CI templates' setting): run i against
// run i. Six seeds that passed before fail now and none the other way:
// McNemar's exact p = 1/2^6 = 0.016, a regression; as independent samples
// (6/20 against 12/20) Fisher's one-sided p = 0.055 would not call it.
TEST(Baseline, RunsOnTheSameSeedsAreComparedPairByPair) {
  const TestFile f = oneTest(0.2);
  const std::vector<RunResult> base = runs("a", 20, 12, 10, 0), now = runs("a", 20, 6, 10, 0);
  std::vector<TestSummary> s = summarise(f, now);
  compareWithBaseline(s, now, base, 0.05);
  ASSERT_TRUE(s[0].compared);
  EXPECT_EQ(s[0].pairs, 20);
  EXPECT_NEAR(s[0].p_rate, 1.0 / 64.0, 1e-12);
  EXPECT_FALSE(s[0].time_compared);  // the six that passed on both sides took the same time: nothing to say
  EXPECT_TRUE(s[0].regressed);
  EXPECT_NEAR(stats::fisherLess(6, 14, 12, 8), 0.0555, 0.0001);  // what the independent test says
  // Slower on every one of ten seeds, by 1..10 s: the signed-rank V = 55,
  // the largest of 2^10 sign patterns: p = 1/1024.
  std::vector<RunResult> slow = runs("a", 10, 10, 10, 0);
  const std::vector<RunResult> base10 = runs("a", 10, 10, 10, 0);
  for (size_t i = 0; i < slow.size(); ++i) slow[i].decided_s += 1.0 + static_cast<double>(i);
  std::vector<TestSummary> t = summarise(f, slow);
  compareWithBaseline(t, slow, base10, 0.05);
  EXPECT_EQ(t[0].pairs, 10);
  EXPECT_DOUBLE_EQ(t[0].p_rate, 1.0);  // no discordant pair
  EXPECT_TRUE(t[0].time_compared);
  EXPECT_NEAR(t[0].p_time, 1.0 / 1024.0, 1e-12);
  EXPECT_TRUE(t[0].regressed);
  // The same program on the same seeds: identical runs, nothing to compare
  // beyond the rate (p = 1).
  std::vector<TestSummary> same = summarise(f, base10);
  compareWithBaseline(same, base10, base10, 0.05);
  EXPECT_DOUBLE_EQ(same[0].p_rate, 1.0);
  EXPECT_FALSE(same[0].time_compared);
  EXPECT_FALSE(same[0].regressed);
}

TEST(Baseline, ATestMissingFromTheBaselineIsNotCompared) {
  const TestFile f = oneTest(0.5);
  std::vector<TestSummary> s = summarise(f, runs("a", 10, 2));
  compareWithBaseline(s, runs("a", 10, 2), runs("other", 10, 10), 0.05);
  EXPECT_FALSE(s[0].compared);
  EXPECT_FALSE(s[0].regressed);
}

}  // namespace
