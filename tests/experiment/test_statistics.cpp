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

// The one-sided Mann-Whitney normal approximation with ties, as R's
// wilcox.test computes it with exact = FALSE and correct = TRUE (its
// documentation, "Details": a normal approximation with continuity
// correction, the variance corrected for ties; the formula in R's
// src/library/stats/R/wilcox.test.R:
//   z = (U - n1 n2 / 2 - 0.5) / sqrt(n1 n2 / 12 ((n1 + n2 + 1) - sum(t^3 - t) / ((n1 + n2)(n1 + n2 - 1))))),
// worked by hand for a small case, and the exact permutation p beside it.
TEST(Statistics, MannWhitneyWithTiesMatchesTheHandComputedApproximation) {
  const std::vector<double> x = {2, 3, 3, 5}, y = {1, 2, 3, 4, 4};
  // Pooled and ranked: 1(y) 1; 2(x) 2(y) 2.5; 3(x) 3(x) 3(y) 5; 4(y) 4(y) 7.5; 5(x) 9.
  // Rank sum of x: 2.5 + 5 + 5 + 9 = 21.5; U = 21.5 - 4 x 5 / 2 = 11.5.
  // Ties: groups of 2, 3 and 2: sum(t^3 - t) = 6 + 24 + 6 = 36.
  // Variance: 20 / 12 x (10 - 36 / (9 x 8)) = 15.8333; z = (11.5 - 10 - 0.5) / 3.97911 = 0.251312.
  const double z = 1.0 / std::sqrt(20.0 / 12.0 * (10.0 - 36.0 / 72.0));
  const double p_hand = 0.5 * std::erfc(z / std::sqrt(2.0));  // 1 - Phi(z) = 0.400786
  const st::MannWhitney m = st::mannWhitneyGreater(x, y);
  EXPECT_FALSE(m.exact);  // ties: the approximation
  EXPECT_DOUBLE_EQ(m.u, 11.5);
  EXPECT_NEAR(m.p, p_hand, 1e-12);  // the same formula: only rounding apart
  EXPECT_NEAR(m.p, 0.400786, 1e-6);
  // Two-sided: twice the tail of |U - mu| - 0.5.
  EXPECT_NEAR(st::mannWhitney(x, y).p, 2 * p_hand, 1e-12);
  // The exact conditional p: every way of choosing which 4 of the 9 pooled
  // values are x (126), U >= 11.5 in 50 of them: 0.3968. The approximation
  // is within 0.005 of it here (tolerance 0.01).
  const std::vector<double> pool = {2, 3, 3, 5, 1, 2, 3, 4, 4};
  int at_least = 0, all = 0;
  for (int mask = 0; mask < (1 << 9); ++mask) {
    if (__builtin_popcount(mask) != 4) continue;
    double u = 0;
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        if ((mask >> i & 1) && !(mask >> j & 1)) u += pool[i] > pool[j] ? 1.0 : pool[i] == pool[j] ? 0.5 : 0.0;
    ++all;
    at_least += u >= 11.5 - 1e-9;
  }
  ASSERT_EQ(all, 126);
  EXPECT_EQ(at_least, 50);
  EXPECT_NEAR(m.p, 50.0 / 126.0, 0.01);
}

// McNemar's exact test, one-sided: P(X >= worse), X ~ Binomial(worse +
// better, 1/2), against the binomial sums counted here.
TEST(Statistics, McNemarExactMatchesTheBinomialTail) {
  EXPECT_NEAR(st::mcnemarWorse(7, 1), 9.0 / 256.0, 1e-15);  // (C(8,7) + C(8,8)) / 2^8
  EXPECT_NEAR(st::mcnemarWorse(6, 0), 1.0 / 64.0, 1e-15);
  EXPECT_NEAR(st::mcnemarWorse(1, 7), 255.0 / 256.0, 1e-15);
  EXPECT_DOUBLE_EQ(st::mcnemarWorse(0, 5), 1.0);  // none worse
  EXPECT_DOUBLE_EQ(st::mcnemarWorse(0, 0), 1.0);  // no discordant pair: no evidence
  for (int worse = 0; worse <= 20; ++worse)
    for (int better = 0; better <= 20; ++better) {
      const int n = worse + better;
      double tail = 0;
      for (int k = worse; k <= n; ++k) tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0));
      tail /= std::pow(2.0, n);
      EXPECT_NEAR(st::mcnemarWorse(worse, better), n ? std::min(1.0, tail) : 1.0, 1e-12) << worse << " " << better;
    }
}

namespace {
// P(V >= v) over all 2^n sign patterns of the ranks (brute force).
double signedRankTail(const std::vector<double>& ranks, double v) {
  const size_t n = ranks.size();
  long at_least = 0;
  for (long mask = 0; mask < (1L << n); ++mask) {
    double s = 0;
    for (size_t i = 0; i < n; ++i)
      if (mask >> i & 1) s += ranks[i];
    at_least += s >= v - 1e-9;
  }
  return static_cast<double>(at_least) / static_cast<double>(1L << n);
}
}  // namespace

// The Wilcoxon signed-rank test, one-sided (differences tend positive):
// exact against a brute-force count over the sign patterns of ranks worked
// by hand (ties and zeros included), against the published table value for
// n = 5, and the normal approximation against R's formula by hand
// (wilcox.test.R: z = (V - n(n+1)/4 - 0.5) / sqrt(n(n+1)(2n+1)/24 - sum(t^3 - t)/48)).
TEST(Statistics, WilcoxonSignedRankMatchesEnumerationAndTheFormula) {
  // Five positive differences: V = 15, the largest of 2^5 patterns: 1/32
  // (tables of the signed-rank distribution, e.g. R's psignrank(14, 5, lower.tail = FALSE)).
  const st::SignedRank all_up = st::wilcoxonGreater({0.1, 0.2, 0.3, 0.4, 0.5});
  EXPECT_TRUE(all_up.exact);
  EXPECT_DOUBLE_EQ(all_up.v, 15);
  EXPECT_NEAR(all_up.p, 1.0 / 32.0, 1e-15);
  // With ties and zeros: d = 1.5, -0.5, 2, 2, -3, 0, 4, 0.5, 0. Zeros dropped
  // (n = 7); |d| ranked: 0.5 0.5 -> 1.5 each; 1.5 -> 3; 2 2 -> 4.5 each; 3 -> 6;
  // 4 -> 7. V (positive ones) = 1.5 + 3 + 4.5 + 4.5 + 7 = 20.5.
  const st::SignedRank w = st::wilcoxonGreater({1.5, -0.5, 2, 2, -3, 0, 4, 0.5, 0});
  EXPECT_EQ(w.n, 7);
  EXPECT_DOUBLE_EQ(w.v, 20.5);
  EXPECT_TRUE(w.exact);
  EXPECT_NEAR(w.p, signedRankTail({1.5, 1.5, 3, 4.5, 4.5, 6, 7}, 20.5), 1e-12);
  EXPECT_NEAR(st::wilcoxonGreater({-1, -2, -3}).p, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(st::wilcoxonGreater({0, 0}).p, 1.0);  // nothing but zeros: no evidence
  // The normal approximation (n > 200): 150 differences of +1 and 60 of -1,
  // all tied in |d|: every rank 105.5; V = 150 x 105.5 = 15825; mean
  // 210 x 211 / 4 = 11077.5; variance 210 x 211 x 421 / 24 - (210^3 - 210) / 48.
  std::vector<double> d(150, 1.0);
  d.insert(d.end(), 60, -1.0);
  const st::SignedRank big = st::wilcoxonGreater(d);
  EXPECT_FALSE(big.exact);
  EXPECT_DOUBLE_EQ(big.v, 15825);
  const double var = 210.0 * 211 * 421 / 24 - (210.0 * 210 * 210 - 210) / 48;
  const double zb = (15825 - 11077.5 - 0.5) / std::sqrt(var);
  EXPECT_NEAR(big.p / (0.5 * std::erfc(zb / std::sqrt(2.0))), 1.0, 1e-9);  // relative: p is 2.7e-10
  // A binomial check of the same: all |d| tied, V is 105.5 x (positives),
  // so P(V >= 15825) = P(Binomial(210, 1/2) >= 150) = 2.2e-10 exactly; the
  // normal approximation with continuity gives 2.7e-10.
  EXPECT_GT(big.p, 1e-10);
  EXPECT_LT(big.p, 5e-10);
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
  EXPECT_NE(s.find("- `A` finds more balls than `B` at position 1 (Holm-adjusted p < 0.05)."), std::string::npos) << s;
  EXPECT_EQ(s.find("at positions 1 and 2"), std::string::npos) << s;
  EXPECT_NE(s.find("| 1 | 10/10 | 0/10 | < 0.001 | < 0.001 |"), std::string::npos) << s;
}

// Five positions, each 8/10 against 2/10: each alone p = 0.023 (Fisher,
// two-sided: 2 x (C(10,8) C(10,2) + 2 C(10,9) C(10,1) + 2) / C(20,10), the
// tables as or less likely), below 0.05; but the section makes 5 + 1 rate
// tests and 6 time tests, and Holm's smallest threshold is 0.05 / 12, so no
// single position is called, while all positions together (40/50 against
// 10/50) are.
TEST(Statistics, TheReportCorrectsForItsManyComparisons) {
  simswift::experiment::Experiment e;
  e.seed = 3;
  e.setups.resize(2);
  e.setups[0].name = "A";
  e.setups[1].name = "B";
  std::vector<TrialResult> results;
  for (int position = 1; position <= 5; ++position) {
    e.balls.push_back({position, 1.0 * position, 0.0, ""});
    for (int i = 0; i < 10; ++i) {
      TrialResult a;
      a.setup = "A";
      a.position = position;
      a.found = i < 8;
      a.seconds = 20 + i;
      results.push_back(a);
      TrialResult b = a;
      b.setup = "B";
      b.found = i < 2;
      results.push_back(b);
    }
  }
  EXPECT_NEAR(simswift::experiment::stats::fisherExact(8, 2, 2, 8), 0.023, 0.0005);
  const std::string s = simswift::experiment::statisticsSection(e, results);
  EXPECT_NE(s.find("| 1 | 8/10 | 2/10 | 0.023 | 0."), std::string::npos) << s;
  EXPECT_EQ(s.find("finds more balls than `B` at position"), std::string::npos) << s;
  EXPECT_NE(s.find("- No position shows a difference at Holm-adjusted p < 0.05."), std::string::npos) << s;
  EXPECT_NE(s.find("40/50 and 10/50, Fisher p < 0.001 (Holm < 0.001) (a difference larger than chance)"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("12 tests in all"), std::string::npos) << s;
}
