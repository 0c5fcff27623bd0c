// Behaviour: the top of the behaviour stack, one tick per perception frame.
// Reads BehaviourInputs only; writes a MotionRequest (for the Blackboard's
// motion_request section) and this robot's SearchPayload (for the team
// packet's free data area), and exposes the FindBall class's result (the
// Blackboard's findball section; the FindBall view draws it).
//
// Order each tick: (1) the FindBall class updates the distribution and its
// suggestion (always, so PenalisedComponent sees the penalty); (2) outside
// PLAYING or while penalised: stand, head centred, roles reset; (3) else the
// configured role; (4) the payload gets the local distribution and the
// segment the 2017 search is heading to.
#pragma once

#include <memory>
#include <optional>

#include "agent/behaviour/BehaviourConfig.hpp"
#include "agent/behaviour/FindBall.hpp"
#include "agent/behaviour/Roles.hpp"
#include "agent/behaviour/SearchPayload.hpp"

namespace agent::behaviour {

struct BehaviourOutput {
  blackboard::MotionRequest request;
  std::optional<SearchPayload> payload;  // FindBall 2017 and striker only
  const char* activity = "";
};

class Behaviour {
 public:
  explicit Behaviour(const BehaviourConfig& c);
  BehaviourOutput tick(const BehaviourInputs& in);
  // The FindBall class's last result (none for the 2016 behaviour).
  const FindBallResult* findBall() const { return findball_ ? &findball_->result() : nullptr; }
  // Target of the 2017 search: segment (0-based, -1 none) and point.
  int searchSegment() const;
  Point2 searchPoint() const;
  const BehaviourConfig& config() const { return c_; }

 private:
  BehaviourConfig c_;
  std::unique_ptr<FindBall> findball_;
  Searcher searcher_;
  Striker striker_;
  int64_t sequence_ = 0;
};

}  // namespace agent::behaviour
