#include "agent/behaviour/TeamDistributionGenerator.hpp"

#include <vector>

namespace agent::behaviour {

TeamDistributionGenerator::TeamDistributionGenerator(
    std::unique_ptr<BallDistributionGenerator> local, double teammate_timeout)
    : local_(std::move(local)), timeout_(teammate_timeout), team_(local_->distribution()) {}

const PositionalDistribution& TeamDistributionGenerator::update(const BehaviourInputs& in,
                                                                double dt) {
  const PositionalDistribution& s = local_->update(in, dt);
  const int j_count = s.size();
  std::vector<double> sum(s.probabilities());  // n = this robot
  robots_ = 1;
  for (const Teammate& t : in.teammates) {
    if (!t.search || t.time_since_heard > timeout_) continue;
    const SearchPayload& r = *t.search;
    // A teammate on another grid cannot be combined segment by segment.
    if (r.columns != s.columns() || r.rows != s.rows() ||
        static_cast<int>(r.probabilities.size()) != j_count)
      continue;
    for (int j = 0; j < j_count; ++j) sum[j] += r.probabilities[j];
    ++robots_;
  }
  std::vector<double> d(j_count);
  for (int j = 0; j < j_count; ++j) d[j] = s.probability(j) * sum[j];
  if (!team_.sameGrid(s)) team_ = s;
  team_.set(d);  // normalises
  return team_;
}

}  // namespace agent::behaviour
