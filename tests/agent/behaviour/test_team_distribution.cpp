// TeamDistributionGenerator (thesis 4.2.1.2): P(D_j) = P(S_j) x sum_n P(R_nj),
// normalised, with three hand-made distributions.
#include <gtest/gtest.h>

#include "agent/behaviour/TeamDistributionGenerator.hpp"

using namespace agent::behaviour;

namespace {

// A local generator that always returns the same distribution.
class FixedGenerator : public BallDistributionGenerator {
 public:
  explicit FixedGenerator(std::vector<double> p) { d_.set(p); }
  const PositionalDistribution& update(const BehaviourInputs&, double) override { return d_; }
  const PositionalDistribution& distribution() const override { return d_; }

 private:
  PositionalDistribution d_;
};

Teammate mate(int player, std::vector<double> p, double heard = 0.1) {
  Teammate t;
  t.player = player;
  t.time_since_heard = heard;
  SearchPayload s;
  s.player = player;
  s.probabilities = std::move(p);
  t.search = s;
  return t;
}

}  // namespace

TEST(TeamDistributionGenerator, ThreeHandMadeDistributions) {
  const std::vector<double> s = {0.30, 0.10, 0.10, 0.10, 0.10, 0.10, 0.10, 0.05, 0.05};
  const std::vector<double> r2 = {0.10, 0.10, 0.10, 0.10, 0.20, 0.10, 0.10, 0.10, 0.10};
  const std::vector<double> r3 = {0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.10, 0.30, 0.30};
  TeamDistributionGenerator g(std::make_unique<FixedGenerator>(s), 2.0);
  BehaviourInputs in;
  in.teammates = {mate(3, r2), mate(4, r3)};
  const PositionalDistribution& d = g.update(in, 0.1);
  EXPECT_EQ(g.robotsCombined(), 3);
  // Sums: .45 .25 .25 .25 .35 .25 .30 .45 .45; products with S:
  // .135 .025 .025 .025 .035 .025 .030 .0225 .0225; total .345.
  const double want[9] = {0.135, 0.025, 0.025, 0.025, 0.035, 0.025, 0.030, 0.0225, 0.0225};
  for (int j = 0; j < 9; ++j) EXPECT_NEAR(d.probability(j), want[j] / 0.345, 1e-12) << j;
  // The local one is what goes to teammates, unchanged.
  EXPECT_NEAR(g.localDistribution().probability(0), 0.30, 1e-12);
}

TEST(TeamDistributionGenerator, IgnoresSilentAndMismatchedTeammates) {
  const std::vector<double> s = {0.30, 0.10, 0.10, 0.10, 0.10, 0.10, 0.10, 0.05, 0.05};
  TeamDistributionGenerator g(std::make_unique<FixedGenerator>(s), 2.0);
  BehaviourInputs in;
  in.teammates = {mate(3, std::vector<double>(9, 1.0 / 9), 5.0)};  // heard 5 s ago
  Teammate odd = mate(4, {0.5, 0.5});  // a 2 x 1 grid
  odd.search->columns = 2;
  odd.search->rows = 1;
  in.teammates.push_back(odd);
  in.teammates.push_back(Teammate{});  // no payload
  const PositionalDistribution& d = g.update(in, 0.1);
  EXPECT_EQ(g.robotsCombined(), 1);
  // Alone: P(D_j) = P(S_j)^2 normalised; sum of squares = .09 + 6 x .01 + 2 x .0025 = .155.
  EXPECT_NEAR(d.probability(0), 0.09 / 0.155, 1e-12);
  EXPECT_NEAR(d.probability(8), 0.0025 / 0.155, 1e-12);
}
