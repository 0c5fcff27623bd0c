#include "agent/behaviour/Behaviour.hpp"

#include <cmath>

namespace agent::behaviour {

Behaviour::Behaviour(const BehaviourConfig& c)
    : c_(c),
      findball_(c.kind == BehaviourKind::FINDBALL_2016 ? nullptr : FindBall::makeDefault(c)),
      searcher_(c, c.kind != BehaviourKind::FINDBALL_2016),
      striker_(c) {}

int Behaviour::searchSegment() const {
  const FindBallBehaviour& b = c_.kind == BehaviourKind::STRIKER
                                   ? striker_.searcher().findBall2017()
                                   : searcher_.findBall2017();
  return b.phase() == PointSearch::Phase::IDLE ? -1 : b.segment();
}

Point2 Behaviour::searchPoint() const {
  if (c_.kind == BehaviourKind::FINDBALL_2016) return searcher_.findBall2016().point();
  return c_.kind == BehaviourKind::STRIKER ? striker_.searcher().findBall2017().point()
                                           : searcher_.findBall2017().point();
}

BehaviourOutput Behaviour::tick(const BehaviourInputs& in) {
  BehaviourOutput out;
  const FindBallResult* fb = findball_ ? &findball_->tick(in) : nullptr;  // (1)

  RoleOutput role;
  const Pose2& p = in.self.pose;
  const bool pose_ok = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
  if (!pose_ok) {  // localisation gave garbage: do not walk on it
    role.body.type = blackboard::ActionType::STAND;
    role.activity = "no pose";
  } else if (in.game.state != GameState::PLAYING || in.game.penalised) {  // (2)
    searcher_.reset();
    striker_.reset();
    role.body.type = blackboard::ActionType::STAND;
    role.activity = in.game.penalised ? "penalised" : "not playing";
  } else if (c_.kind == BehaviourKind::STRIKER) {  // (3)
    role = striker_.tick(in, fb);
  } else {
    role = searcher_.tick(in, fb);
  }

  out.request.body = role.body;
  out.request.head = role.head;
  out.request.sequence = ++sequence_;
  out.activity = role.activity;

  if (fb) {  // (4)
    SearchPayload p;
    p.player = in.player;
    p.columns = fb->local.columns();
    p.rows = fb->local.rows();
    p.probabilities = fb->local.probabilities();
    p.segment = role.searching ? searchSegment() : -1;
    if (p.segment >= 0) p.point = searchPoint();
    out.payload = p;
  }
  return out;
}

}  // namespace agent::behaviour
