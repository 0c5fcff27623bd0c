#include "agent/behaviour/ActionsBehaviour.hpp"

#include <algorithm>

namespace agent::behaviour {

ActionsBehaviour::ActionsBehaviour(std::vector<ActionStep> steps) : steps_(std::move(steps)) {
  std::stable_sort(steps_.begin(), steps_.end(),
                   [](const ActionStep& a, const ActionStep& b) { return a.t < b.t; });
}

void ActionsBehaviour::request(blackboard::MotionRequest& r, const blackboard::BodyCommand& body,
                                const blackboard::HeadCommand* head) {
  r.body = body;
  if (head) r.head = *head;
  ++r.sequence;  // a new request (a repeated kick kicks again)
}

void ActionsBehaviour::update(const In& in, Out& out) {
  using blackboard::GameStateId;
  const double t = in.get<blackboard::FrameInfo>().time;
  const blackboard::GameInfo& game = in.get<blackboard::GameInfo>();
  blackboard::MotionRequest& req = out.get<blackboard::MotionRequest>();
  const bool hold = game.known && (game.penalised || game.state == GameStateId::INITIAL ||
                                   game.state == GameStateId::SET || game.state == GameStateId::FINISHED);
  blackboard::BodyCommand stand;
  stand.type = blackboard::ActionType::STAND;
  if (!started_) {
    current_ = stand;
    request(req, stand, nullptr);
    started_ = true;
  }
  while (next_ < steps_.size() && steps_[next_].t <= t + 1e-9) {
    const ActionStep& s = steps_[next_++];
    if (s.body.type != blackboard::ActionType::NONE) current_ = s.body;
    if (!hold) request(req, s.body, s.has_head ? &s.head : nullptr);
  }
  if (hold != held_) request(req, hold ? stand : current_, nullptr);
  held_ = hold;
}

}  // namespace agent::behaviour
