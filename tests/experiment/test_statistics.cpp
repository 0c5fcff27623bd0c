// The report's statistics against textbook examples and values recomputed
// by hand (brute-force enumeration, the Wilson formula), and the report's
// statistics section from a fixed results set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "app/experiment/Report.hpp"
#include "app/experiment/Statistics.hpp"

namespace st = simswift::experiment::stats;
using simswift::experiment::TrialResult;

TEST(Statistics, WilsonIntervalsMatchTheFormula) {
  // 8 of 10: [0.4902, 0.9433]; 0 of 10: [0, 0.2775]; 10 of 10: [0.7225, 1].
  EXPECT_NEAR(st::wilson(8, 10).lo, 0.490162, 1e-5);
  EXPECT_NEAR(st::wilson(8, 10).hi, 0.943318, 1e-5);
  EXPECT_NEAR(st::wilson(0, 10).lo, 0.0, 1e-12);
  EXPECT_NEAR(st::wilson(0, 10).hi, 0.277533, 1e-5);
  EXPECT_NEAR(st::wilson(10, 10).lo, 0.722467, 1e-5);
  EXPECT_DOUBLE_EQ(st::wilson(10, 10).hi, 1.0);
  EXPECT_DOUBLE_EQ(st::wilson(0, 0).hi, 1.0);  // no trials: nothing known
}

TEST(Statistics, FishersExactTestMatchesTextbookTables) {
  // Wikipedia's "Fisher's exact test" example (men / women dieting): p = 0.002759.
  EXPECT_NEAR(st::fisherExact(1, 9, 11, 3), 0.0027595, 1e-6);
  // Fisher's lady tasting tea, 3 of 4 right: p = 0.4857.
  EXPECT_NEAR(st::fisherExact(3, 1, 1, 3), 0.4857143, 1e-6);
  EXPECT_NEAR(st::fisherExact(10, 0, 3, 7), 0.0030960, 1e-6);
  EXPECT_NEAR(st::fisherExact(5, 5, 5, 5), 1.0, 1e-9);
}

TEST(Statistics, MannWhitneyExactAndWithTies) {
  // Complete separation of 5 and 5: U = 0, p = 2 / C(10, 5) = 0.00794 (exact).
  const st::MannWhitney a = st::mannWhitney({1, 2, 3, 4, 5}, {6, 7, 8, 9, 10});
  EXPECT_DOUBLE_EQ(a.u, 0.0);
  EXPECT_TRUE(a.exact);
  EXPECT_NEAR(a.p, 2.0 / 252.0, 1e-12);
  // U = 17 of 20 pairs: p = 0.1111 by enumerating all 126 splits.
  const st::MannWhitney b = st::mannWhitney({19, 22, 16, 29, 24}, {20, 11, 17, 12});
  EXPECT_DOUBLE_EQ(b.u, 17.0);
  EXPECT_NEAR(b.p, 0.111111, 1e-6);
  // Ties: the normal approximation with tie and continuity corrections.
  const st::MannWhitney c = st::mannWhitney({1, 2, 2, 3, 3, 3, 4}, {3, 4, 4, 5, 5, 6});
  EXPECT_FALSE(c.exact);
  EXPECT_DOUBLE_EQ(c.u, 3.5);
  EXPECT_NEAR(c.p, 0.0129999, 1e-6);
}

TEST(Statistics, BootstrapIsSeededAndBracketsTheMean) {
  const std::vector<double> xs = {12.5, 30.1, 8.0, 45.2, 22.3, 17.9, 60.4, 25.0};
  const st::Interval a = st::bootstrapMean(xs, 42), b = st::bootstrapMean(xs, 42), c = st::bootstrapMean(xs, 43);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  EXPECT_NE(a.lo, c.lo);
  EXPECT_EQ(st::bootstrapMean({7.0}, 1).lo, 7.0);
}

// The interval's level: over 1000 samples of 30 from a normal distribution
// (mean 30, sd 8; seeded), the 95 % interval must hold the true mean in
// about 95 % of them and be as wide as the mean's known standard error says.
// The percentile bootstrap of a mean covers a little less than its level at
// this size: it uses the sample's sd with divisor n and normal, not t,
// quantiles, so P(|t_29| < 1.96 sqrt(29/30)) = 0.937 is expected. Tolerance
// [0.92, 0.96]: about 2 standard errors of a 1000-trial coverage (0.0077)
// either side. A 90 % or a 99 % interval (coverage 0.88 / 0.98) fails it.
// Width: E[2 x 1.96 x sd_n / sqrt(n)] = 0.975 x 3.92 x 8 / sqrt(30) (the sd
// with divisor n, times c4(30) = 0.9914), within 3 %.
TEST(Statistics, BootstrapIntervalHasItsLevelAndTheStandardErrorsWidth) {
  const double mu = 30, sigma = 8;
  const int n = 30, samples = 1000;
  std::mt19937_64 rng(2017);
  auto uniform = [&rng] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };  // (0, 1)
  int covered = 0;
  double width = 0;
  for (int k = 0; k < samples; ++k) {
    std::vector<double> xs;
    while (static_cast<int>(xs.size()) < n) {  // Box-Muller: two normals per two uniforms
      const double r = std::sqrt(-2 * std::log(uniform())), phi = 2 * M_PI * uniform();
      xs.push_back(mu + sigma * r * std::cos(phi));
      xs.push_back(mu + sigma * r * std::sin(phi));
    }
    xs.resize(n);
    const st::Interval iv = st::bootstrapMean(xs, 1000 + static_cast<uint64_t>(k));
    ASSERT_LE(iv.lo, iv.hi);
    covered += iv.lo <= mu && mu <= iv.hi;
    width += (iv.hi - iv.lo) / samples;
  }
  const double coverage = static_cast<double>(covered) / samples;
  EXPECT_GE(coverage, 0.92);
  EXPECT_LE(coverage, 0.96);
  const double expected_width = 0.975 * 2 * 1.959964 * sigma / std::sqrt(static_cast<double>(n));
  EXPECT_NEAR(width / expected_width, 1.0, 0.03) << "mean width " << width << ", expected " << expected_width;
  std::printf("bootstrap: coverage %.3f over %d samples, mean width %.3f (expected %.3f)\n", coverage, samples, width,
              expected_width);
}

// A fixed results set: setup A finds at position 1 in 10 of 10, B in 0 of
// 10; at position 2 both 5 of 10. The section says so in words.
TEST(Statistics, TheReportSaysWhichDifferencesAreLargerThanChance) {
  simswift::experiment::Experiment e;
  e.seed = 3;
  e.setups.resize(2);
  e.setups[0].name = "A";
  e.setups[1].name = "B";
  e.balls = {{1, 1.0, 0.0, ""}, {2, 2.0, 0.0, ""}};
  std::vector<TrialResult> results;
  for (int i = 0; i < 10; ++i) {
    TrialResult a;
    a.setup = "A";
    a.position = 1;
    a.found = true;
    a.seconds = 10 + i;
    results.push_back(a);
    TrialResult b = a;
    b.setup = "B";
    b.found = false;
    results.push_back(b);
    for (const char* s : {"A", "B"}) {
      TrialResult c;
      c.setup = s;
      c.position = 2;
      c.found = i % 2 == 0;
      c.seconds = 30 + i;
      results.push_back(c);
    }
  }
  TrialResult failed;
  failed.setup = "A";
  failed.position = 2;
  failed.failed = "t1p1: program killed by signal 11 (Segmentation fault)";
  results.push_back(failed);  // not counted
  const std::string s = simswift::experiment::statisticsSection(e, results);
  EXPECT_NE(s.find("| 1 | 10/10 | 100 % [72, 100] % | 14.50 "), std::string::npos) << s;
  EXPECT_NE(s.find("| 2 | 5/10 |"), std::string::npos) << s;
  EXPECT_NE(s.find("- `A` finds more balls than `B` at position 1 (p < 0.05)."), std::string::npos) << s;
  EXPECT_EQ(s.find("at positions 1 and 2"), std::string::npos) << s;
  EXPECT_NE(s.find("| 1 | 10/10 | 0/10 | < 0.001 |"), std::string::npos) << s;
}
