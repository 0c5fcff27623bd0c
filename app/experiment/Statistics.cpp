#include "app/experiment/Statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/hypergeometric.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <random>

namespace simswift::experiment::stats {

namespace {

double zFor(double confidence) {
  const boost::math::normal n;
  return boost::math::quantile(n, 1.0 - (1.0 - confidence) / 2.0);
}

}  // namespace

double median(std::vector<double> xs) {
  if (xs.empty()) return 0;
  std::sort(xs.begin(), xs.end());
  const size_t n = xs.size();
  return n % 2 ? xs[n / 2] : (xs[n / 2 - 1] + xs[n / 2]) / 2;
}

Interval wilson(int k, int n, double confidence) {
  if (n <= 0) return {0.0, 1.0};
  const double z = zFor(confidence), p = static_cast<double>(k) / n, z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

Interval bootstrapMean(const std::vector<double>& xs, uint64_t seed, int resamples, double confidence) {
  if (xs.empty()) return {};
  if (xs.size() == 1) return {xs[0], xs[0]};
  std::mt19937_64 rng(seed);  // mt19937_64's output sequence is fixed by the standard
  const uint64_t n = xs.size();
  std::vector<double> means(static_cast<size_t>(resamples));
  for (double& m : means) {
    double sum = 0;
    // Index by the top bits of a 64-bit draw (no distribution object: its
    // algorithm is implementation-defined, the draws are not).
    for (uint64_t i = 0; i < n; ++i) sum += xs[static_cast<size_t>((static_cast<unsigned __int128>(rng()) * n) >> 64)];
    m = sum / static_cast<double>(n);
  }
  std::sort(means.begin(), means.end());
  const double tail = (1.0 - confidence) / 2.0;
  auto at = [&](double q) {
    const double pos = q * (resamples - 1);
    const size_t i = static_cast<size_t>(std::floor(pos));
    const double f = pos - static_cast<double>(i);
    return i + 1 < means.size() ? means[i] * (1 - f) + means[i + 1] * f : means[i];
  };
  return {at(tail), at(1.0 - tail)};
}

double fisherExact(int a, int b, int c, int d) {
  const unsigned r1 = static_cast<unsigned>(a + b), c1 = static_cast<unsigned>(a + c),
                 n = static_cast<unsigned>(a + b + c + d);
  if (n == 0) return 1.0;
  // a ~ hypergeometric: c1 "found" among n, r1 drawn (row 1).
  const boost::math::hypergeometric_distribution<double> h(c1, r1, n);
  const unsigned lo = r1 + c1 > n ? r1 + c1 - n : 0, hi = std::min(r1, c1);
  const double p_obs = boost::math::pdf(h, static_cast<unsigned>(a));
  double p = 0;
  for (unsigned k = lo; k <= hi; ++k) {
    const double pk = boost::math::pdf(h, k);
    if (pk <= p_obs * (1 + 1e-7)) p += pk;  // relative tolerance: ties in probability count
  }
  return std::min(1.0, p);
}

namespace {

// U of x against y (pairs with x > y, ties 1/2) from the pooled ranks, and
// the tie groups' sum of t^3 - t.
struct UStat {
  double u = 0;
  bool ties = false;
  double tie_term = 0;
};

UStat uStatistic(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<std::pair<double, int>> all;
  for (double v : x) all.push_back({v, 0});
  for (double v : y) all.push_back({v, 1});
  std::sort(all.begin(), all.end());
  const size_t n = all.size(), n1 = x.size();
  UStat s;
  double rank_sum_x = 0;
  for (size_t i = 0; i < n;) {
    size_t j = i;
    while (j < n && all[j].first == all[i].first) ++j;
    const double t = static_cast<double>(j - i);
    if (t > 1) s.ties = true;
    s.tie_term += t * t * t - t;
    const double mean_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (size_t k = i; k < j; ++k)
      if (all[k].second == 0) rank_sum_x += mean_rank;
    i = j;
  }
  s.u = rank_sum_x - static_cast<double>(n1) * (n1 + 1) / 2.0;
  return s;
}

// The number of arrangements of n1 x and n2 y values with each U (no ties),
// by the recurrence N(u; m, k) = N(u - k; m - 1, k) + N(u; m, k - 1).
std::vector<double> exactUCounts(size_t n1, size_t n2) {
  const size_t umax = n1 * n2;
  std::vector<std::vector<double>> prev(n2 + 1, std::vector<double>(umax + 1, 0.0));
  for (size_t k = 0; k <= n2; ++k) prev[k][0] = 1;  // m = 0: U = 0 once
  for (size_t m = 1; m <= n1; ++m) {
    std::vector<std::vector<double>> cur(n2 + 1, std::vector<double>(umax + 1, 0.0));
    cur[0][0] = 1;
    for (size_t k = 1; k <= n2; ++k)
      for (size_t u = 0; u <= m * k; ++u) cur[k][u] = (u >= k ? prev[k][u - k] : 0.0) + cur[k - 1][u];
    prev.swap(cur);
  }
  return prev[n2];
}

// The exact probability of the U values `in_tail` picks, under the null.
template <class InTail>
double exactTail(size_t n1, size_t n2, InTail in_tail) {
  const std::vector<double> counts = exactUCounts(n1, n2);
  double total = 0, tail = 0;
  for (size_t u = 0; u < counts.size(); ++u) {
    total += counts[u];
    if (in_tail(static_cast<double>(u))) tail += counts[u];
  }
  return tail / total;
}

// The normal approximation's variance of U with the tie correction.
double uVariance(size_t n1, size_t n2, double tie_term) {
  const double nn = static_cast<double>(n1 + n2);
  return static_cast<double>(n1) * n2 / 12.0 * ((nn + 1) - tie_term / (nn * (nn - 1)));
}

}  // namespace

MannWhitney mannWhitney(const std::vector<double>& x, const std::vector<double>& y) {
  MannWhitney r;
  const size_t n1 = x.size(), n2 = y.size();
  if (n1 == 0 || n2 == 0) return r;
  const UStat s = uStatistic(x, y);
  r.u = s.u;
  const double mu = static_cast<double>(n1) * n2 / 2.0;
  if (!s.ties && n1 <= 30 && n2 <= 30) {
    const double u_low = std::min(r.u, static_cast<double>(n1 * n2) - r.u);
    r.p = std::min(1.0, 2.0 * exactTail(n1, n2, [&](double u) { return u <= u_low + 1e-9; }));
    r.exact = true;
    return r;
  }
  const double var = uVariance(n1, n2, s.tie_term);
  if (var <= 0) return r;  // every value equal: no evidence of a difference
  const double z = (std::fabs(r.u - mu) - 0.5) / std::sqrt(var);
  const boost::math::normal normal;
  r.p = std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(normal, std::max(0.0, z))));
  return r;
}

MannWhitney mannWhitneyGreater(const std::vector<double>& x, const std::vector<double>& y) {
  MannWhitney r;
  const size_t n1 = x.size(), n2 = y.size();
  if (n1 == 0 || n2 == 0) return r;
  const UStat s = uStatistic(x, y);
  r.u = s.u;
  if (!s.ties && n1 <= 30 && n2 <= 30) {
    r.p = std::min(1.0, exactTail(n1, n2, [&](double u) { return u >= r.u - 1e-9; }));
    r.exact = true;
    return r;
  }
  const double var = uVariance(n1, n2, s.tie_term);
  if (var <= 0) return r;
  const double z = (r.u - static_cast<double>(n1) * n2 / 2.0 - 0.5) / std::sqrt(var);
  const boost::math::normal normal;
  r.p = std::min(1.0, boost::math::cdf(boost::math::complement(normal, z)));
  return r;
}

double fisherLess(int a, int b, int c, int d) {
  const unsigned r1 = static_cast<unsigned>(a + b), c1 = static_cast<unsigned>(a + c),
                 n = static_cast<unsigned>(a + b + c + d);
  if (n == 0) return 1.0;
  const boost::math::hypergeometric_distribution<double> h(c1, r1, n);
  return std::min(1.0, boost::math::cdf(h, static_cast<unsigned>(a)));
}

double mcnemarWorse(int worse, int better) {
  const int n = worse + better;
  if (n <= 0 || worse <= 0) return 1.0;
  const boost::math::binomial_distribution<double> b(n, 0.5);
  // P(X >= worse) = P(X > worse - 1).
  return std::min(1.0, boost::math::cdf(boost::math::complement(b, static_cast<double>(worse - 1))));
}

SignedRank wilcoxonGreater(const std::vector<double>& d) {
  SignedRank r;
  std::vector<std::pair<double, bool>> a;  // |d|, positive
  for (double x : d)
    if (x != 0) a.push_back({std::fabs(x), x > 0});
  std::sort(a.begin(), a.end());
  const size_t n = a.size();
  r.n = static_cast<int>(n);
  if (n == 0) return r;
  // Doubled mid-ranks (integers: i + 1 + j for the tie group [i, j)).
  std::vector<long> rank2(n);
  double tie_term = 0;  // sum of t^3 - t over the tie groups
  for (size_t i = 0; i < n;) {
    size_t j = i;
    while (j < n && a[j].first == a[i].first) ++j;
    for (size_t k = i; k < j; ++k) rank2[k] = static_cast<long>(i + 1 + j);
    const double t = static_cast<double>(j - i);
    tie_term += t * t * t - t;
    i = j;
  }
  long v2 = 0;  // 2 v
  for (size_t k = 0; k < n; ++k)
    if (a[k].second) v2 += rank2[k];
  r.v = static_cast<double>(v2) / 2.0;
  if (n <= 200) {
    // Under the null each difference is positive or negative with
    // probability 1/2, independently: count the sign patterns by 2 v.
    const long total2 = static_cast<long>(n * (n + 1));
    std::vector<double> ways(static_cast<size_t>(total2) + 1, 0.0);
    ways[0] = 1;
    long reach = 0;
    for (size_t k = 0; k < n; ++k) {
      reach += rank2[k];
      for (long s = reach; s >= rank2[k]; --s) ways[static_cast<size_t>(s)] += ways[static_cast<size_t>(s - rank2[k])];
    }
    double tail = 0, all = 0;
    for (long s = 0; s <= total2; ++s) {
      all += ways[static_cast<size_t>(s)];
      if (s >= v2) tail += ways[static_cast<size_t>(s)];
    }
    r.p = std::min(1.0, tail / all);
    r.exact = true;
    return r;
  }
  const double nn = static_cast<double>(n);
  const double mean = nn * (nn + 1) / 4.0;
  const double var = nn * (nn + 1) * (2 * nn + 1) / 24.0 - tie_term / 48.0;
  if (var <= 0) return r;
  const boost::math::normal normal;
  r.p = std::min(1.0, boost::math::cdf(boost::math::complement(normal, (r.v - mean - 0.5) / std::sqrt(var))));
  return r;
}

std::vector<double> holm(const std::vector<double>& p) {
  const size_t m = p.size();
  std::vector<size_t> order(m);
  for (size_t i = 0; i < m; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
  std::vector<double> adj(m);
  double running = 0;
  for (size_t k = 0; k < m; ++k) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - k) * p[order[k]]));
    adj[order[k]] = running;
  }
  return adj;
}

}  // namespace simswift::experiment::stats
