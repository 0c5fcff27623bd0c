#include "agent/motion/ActionScript.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace agent::motion {

ScriptedBehaviour::ScriptedBehaviour(std::vector<ActionStep> steps) : steps_(std::move(steps)) {
  std::stable_sort(steps_.begin(), steps_.end(),
                   [](const ActionStep& a, const ActionStep& b) { return a.t < b.t; });
}

void ScriptedBehaviour::request(blackboard::MotionRequest& r, const blackboard::BodyCommand& body,
                                const blackboard::HeadCommand* head) {
  r.body = body;
  if (head) r.head = *head;
  ++r.sequence;  // a new request (a repeated kick kicks again)
}

void ScriptedBehaviour::update(const In& in, Out& out) {
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

bool parseActionType(const std::string& name, blackboard::ActionType* out) {
  using blackboard::ActionType;
  std::string n = name;
  for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (int i = 0; i < static_cast<int>(ActionType::NUM_ACTION_TYPES); ++i) {
    const auto t = static_cast<ActionType>(i);
    if (n == blackboard::actionName(t)) {
      *out = t;
      return true;
    }
  }
  return false;
}

}  // namespace agent::motion
