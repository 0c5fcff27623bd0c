// The report's statistics: 95 % intervals for a find rate (Wilson score)
// and for a mean find time (percentile bootstrap over trials, seeded), and
// two-sided tests of a difference between two components on the same
// positions: Fisher's exact test (find rates, a 2 x 2 table) and the
// Mann-Whitney U test (find times); for paired runs (`simswift test
// --baseline` on the same seeds) McNemar's exact test and the Wilcoxon
// signed-rank test; Holm's adjustment for a family of them (the one home
// of it). Distributions from Boost.Math.
#pragma once

#include <cstdint>
#include <vector>

namespace simswift::experiment::stats {

// The median (the mean of the two middle values for an even count; 0 if empty).
double median(std::vector<double> xs);

struct Interval {
  double lo = 0, hi = 0;
};

// Wilson score interval for k successes in n trials (n = 0: [0, 1]).
Interval wilson(int k, int n, double confidence = 0.95);

// Percentile bootstrap interval of the mean of xs: `resamples` resamples
// with replacement drawn from a generator seeded with `seed` (the same seed
// gives the same interval). Empty xs: [0, 0]; one value: [x, x].
Interval bootstrapMean(const std::vector<double>& xs, uint64_t seed, int resamples = 2000,
                       double confidence = 0.95);

// Two-sided Fisher's exact test of the 2 x 2 table {{a, b}, {c, d}}
// (rows: components, columns: found / not found): the probability, under
// the hypergeometric null with the margins fixed, of a table at most as
// likely as this one.
double fisherExact(int a, int b, int c, int d);

// Two-sided Mann-Whitney U test of x against y. Exact (the U distribution
// by counting) when there are no ties and both samples have at most 30
// values; otherwise the normal approximation with tie and continuity
// corrections. u = U of x (pairs with x > y, ties counting 1/2).
struct MannWhitney {
  double u = 0;
  double p = 1;
  bool exact = false;
};
MannWhitney mannWhitney(const std::vector<double>& x, const std::vector<double>& y);

// One-sided Mann-Whitney: the evidence that x tends to be larger than y
// (p = P(U >= u) under the null; exact or normal as above).
MannWhitney mannWhitneyGreater(const std::vector<double>& x, const std::vector<double>& y);

// One-sided Fisher's exact test of {{a, b}, {c, d}}: the probability of a or
// fewer in the first cell with the margins fixed (row 1's rate is lower).
double fisherLess(int a, int b, int c, int d);

// Paired comparisons: run i of both sides started from the same seed (the
// same placement, the same noise), so each pair is one observation.

// One-sided McNemar's exact test of paired pass/fail outcomes: of the
// discordant pairs, `worse` passed before and fail now, `better` the other
// way. Under the null either way is as likely (probability 1/2), so the p
// is P(X >= worse) for X ~ Binomial(worse + better, 1/2); 1 with no
// discordant pair.
double mcnemarWorse(int worse, int better);

// One-sided Wilcoxon signed-rank test: the evidence that the paired
// differences d tend to be positive. Zero differences are dropped (as
// Wilcoxon's test and R's wilcox.test do); the others are ranked by |d|,
// ties by their mean rank; v = the sum of the positive differences' ranks,
// n = the differences left. Exact (the permutation distribution of v under
// random signs, ties included, counted over half-ranks) for n <= 200;
// otherwise the normal approximation with tie and continuity corrections.
struct SignedRank {
  double v = 0;
  double p = 1;
  int n = 0;
  bool exact = false;
};
SignedRank wilcoxonGreater(const std::vector<double>& d);

// Holm's step-down adjustment of p-values (family-wise error at most the
// level used), in the input's order.
std::vector<double> holm(const std::vector<double>& p);

}  // namespace simswift::experiment::stats
