#include "agent/motion/ActionScript.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace agent::motion {

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
