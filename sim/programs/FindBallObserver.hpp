// The program side of the FindBall view (sim/views/FindBallView.hpp): what
// the robot program's FindBall search shows, turned into the view's plain
// data. The view and its recorder know nothing of the robot program; a
// builtin program's driver fills them through the observer hook
// (ProgramDriver::findBallView) from its Blackboard's findball section.
// Units mm and rad, field frame.
#pragma once

#include <optional>
#include <string>

#include "agent/behaviour/Behaviour.hpp"
#include "agent/behaviour/BehaviourModule.hpp"
#include "agent/behaviour/PositionalDistribution.hpp"
#include "agent/blackboard/FindBallInfo.hpp"
#include "sim/views/FindBallView.hpp"

namespace simswift::programs {

using sim::views::FindBallViewData;
using sim::views::ViewRobot;

// Copies a distribution's grid and probabilities into the view data.
void setDistribution(FindBallViewData& d, const agent::behaviour::PositionalDistribution& p);
// A teammate from the Blackboard's findball section, as drawn.
ViewRobot viewRobot(const agent::blackboard::FindBallTeammate& t);
// The view of one robot's findball section (field mm, rad).
FindBallViewData viewFromInfo(const agent::blackboard::FindBallInfo& fb, int player, const std::string& tag,
                              double field_length = common::field::kLength, double field_width = common::field::kWidth);
// The same, or nothing when the section is not active (no search runs).
std::optional<FindBallViewData> observedView(const agent::blackboard::FindBallInfo& fb, int player,
                                             const std::string& tag);
// One robot's view, as the thesis's tab shows it: the distribution its
// FindBall class produced (team distribution for 2017), itself and its
// search point, its teammates and the points their packets name.
// The 2016 behaviour has no distribution: drawn uniform.
FindBallViewData robotView(const agent::behaviour::BehaviourInputs& in, const agent::behaviour::Behaviour& behaviour);

}  // namespace simswift::programs
