#include "sim/programs/FindBallObserver.hpp"

#include <cstdio>

namespace simswift::programs {

void setDistribution(FindBallViewData& d, const agent::behaviour::PositionalDistribution& p) {
  d.field_length = p.length();
  d.field_width = p.width();
  d.columns = p.columns();
  d.rows = p.rows();
  d.probabilities = p.probabilities();
}

ViewRobot viewRobot(const agent::blackboard::FindBallTeammate& t) {
  ViewRobot r;
  r.player = t.player;
  r.x = t.x;
  r.y = t.y;
  r.theta = t.theta;
  r.has_target = t.has_target;
  r.target_x = t.target_x;
  r.target_y = t.target_y;
  return r;
}

FindBallViewData robotView(const agent::behaviour::BehaviourInputs& in,
                           const agent::behaviour::Behaviour& behaviour) {
  using namespace agent::behaviour;
  FindBallViewData d;
  const BehaviourConfig& c = behaviour.config();
  if (const FindBallResult* fb = behaviour.findBall()) {
    setDistribution(d, fb->distribution);
  } else {
    setDistribution(d, PositionalDistribution::fromConfig(c.grid, c.field));
  }
  ViewRobot self;
  self.player = in.player;
  self.x = in.self.pose.x;
  self.y = in.self.pose.y;
  self.theta = in.self.pose.theta;
  self.self = true;
  const bool has = c.kind == BehaviourKind::FINDBALL_2016 || behaviour.searchSegment() >= 0;
  if (has) {
    self.has_target = true;
    self.target_x = behaviour.searchPoint().x;
    self.target_y = behaviour.searchPoint().y;
  }
  d.robots.push_back(self);
  // Teammates through the findball section's conversion (BehaviourModule).
  for (const Teammate& t : in.teammates) d.robots.push_back(viewRobot(findBallTeammate(t)));
  char caption[96];
  std::snprintf(caption, sizeof caption, "t=%.1f s  robot %d  %s", in.time, in.player,
                behaviourKindName(c.kind));
  d.caption = caption;
  return d;
}

FindBallViewData viewFromInfo(const agent::blackboard::FindBallInfo& fb, int player, const std::string& tag,
                              double field_length, double field_width) {
  FindBallViewData d;
  d.field_length = field_length;
  d.field_width = field_width;
  d.columns = fb.columns;
  d.rows = fb.rows;
  d.probabilities = fb.team;
  ViewRobot self;
  self.player = player;
  self.x = fb.pose_x;
  self.y = fb.pose_y;
  self.theta = fb.pose_theta;
  self.self = true;
  self.has_target = fb.has_point;
  self.target_x = fb.point_x;
  self.target_y = fb.point_y;
  d.robots.push_back(self);
  for (const agent::blackboard::FindBallTeammate& t : fb.teammates) d.robots.push_back(viewRobot(t));
  namespace ab = agent::behaviour;
  const char* kind = ab::behaviourKindName(static_cast<ab::BehaviourKind>(fb.kind));  // "?" outside the table
  char caption[128];
  std::snprintf(caption, sizeof caption, "t=%.1f s  %s  %s  %s", fb.time, tag.c_str(), kind, fb.activity);
  d.caption = caption;
  return d;
}

std::optional<FindBallViewData> observedView(const agent::blackboard::FindBallInfo& fb, int player,
                                             const std::string& tag) {
  if (!fb.active) return std::nullopt;
  return viewFromInfo(fb, player, tag);
}

}  // namespace simswift::programs
