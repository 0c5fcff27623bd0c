// DistributedUtilityCalculator (thesis 4.2.2.2): the local utility shared
// among the robots that would search the segment,
//   U_d(S_j) = U_l(S_j) / (V_j + 1),
// V_j = teammates already heading to S_j (from their packets; penalised or
// silent teammates not counted).
//
// Which divisor: the thesis writes U_l / V_j with V_j "the number of
// teammates already visiting S_j". Taken literally that divides by zero for
// every segment nobody visits, and clamping V_j to 1 would make one visitor
// cost nothing. The argument the thesis gives is that k robots searching one
// segment each add only 1/k of new information, so the divisor here is the
// number of robots that would be there if this robot went too: V_j + 1. With
// two teammates heading to segment 5 its utility is divided by 3.
//
// With StrategyConfig::exclusive_segments (the default) a segment a teammate
// has chosen and has the better claim to (nearer its centre; ties: the
// lower player number) is worth 0 to this robot: no two teammates are sent
// to one segment (and so to one search point). The thesis's own argument
// for the division (robots heading to one place collide and fall) is the
// reason; the division alone still let two robots pick one segment in the
// same tick, or stay on it when its utility dwarfed the rest.
#pragma once

#include <memory>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/UtilityCalculator.hpp"

namespace agent::behaviour {

class DistributedUtilityCalculator : public UtilityCalculator {
 public:
  DistributedUtilityCalculator(std::unique_ptr<UtilityCalculator> local, const StrategyConfig& c)
      : local_(std::move(local)), config_(c) {}
  double utility(const PositionalDistribution& d, int segment,
                 const BehaviourInputs& in) const override;
  // V_j: teammates heard within teammate_timeout, not penalised, whose
  // packet names `segment` (on the same grid) as their chosen segment.
  int visitors(const PositionalDistribution& d, int segment, const BehaviourInputs& in) const;
  // A teammate counted by visitors() has the better claim to `segment`.
  bool claimedByTeammate(const PositionalDistribution& d, int segment, const BehaviourInputs& in) const;

 private:
  std::unique_ptr<UtilityCalculator> local_;
  StrategyConfig config_;
};

}  // namespace agent::behaviour
