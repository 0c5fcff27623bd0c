#include "agent/motion/ActionScript.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace agent::motion {

ScriptedBehaviour::ScriptedBehaviour(std::vector<ActionStep> steps) : steps_(std::move(steps)) {
  std::stable_sort(steps_.begin(), steps_.end(),
                   [](const ActionStep& a, const ActionStep& b) { return a.t < b.t; });
}

void ScriptedBehaviour::run(blackboard::Blackboard& board) { runAt(board.frame.read().time, board); }

void ScriptedBehaviour::runAt(double t, blackboard::Blackboard& board) {
  if (!started_) {
    board.motion_request.update([](blackboard::MotionRequest& r) {
      r.body.type = blackboard::ActionType::STAND;
      ++r.sequence;
    });
    started_ = true;
  }
  while (next_ < steps_.size() && steps_[next_].t <= t + 1e-9) {
    const ActionStep& s = steps_[next_++];
    board.motion_request.update([&](blackboard::MotionRequest& r) {
      r.body = s.body;
      if (s.has_head) r.head = s.head;
      ++r.sequence;  // a new request (a repeated kick kicks again)
    });
  }
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
