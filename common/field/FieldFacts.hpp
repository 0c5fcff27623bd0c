// The SPL 2017 field for the robot code: the dimensions of the RoboCup
// Standard Platform League Rule Book 2017 (its field figure and table), as
// a team writes them down. The one home of these numbers in agent/: the
// localisation's FieldModel, the behaviour's FieldGeometry and grid and the
// kick's target read them; sim/ may read them too (the FindBall view draws
// the field the robot believes in). The simulator's own field is
// fields/spl_2017.yaml; tests/world/test_field_model_agreement.cpp holds
// the two against each other.
//
// Field frame: origin at the centre spot, x toward the opponent goal, y
// left; mm. Lengths between lines are between the lines' centres.
#pragma once

namespace common::field {

constexpr double kLength = 9000;               // mm, goal line to goal line
constexpr double kWidth = 6000;                // mm, touch line to touch line
constexpr double kLineWidth = 50;              // mm
constexpr double kPenaltyAreaDepth = 600;      // mm, from the goal line
constexpr double kPenaltyAreaWidth = 2200;     // mm, along the goal line
constexpr double kPenaltyMarkDistance = 1300;  // mm, from the goal line
constexpr double kCentreCircleDiameter = 1500; // mm
constexpr double kBorderStripWidth = 700;      // mm of carpet outside the lines
constexpr double kGoalPostDiameter = 100;      // mm
constexpr double kGoalInnerWidth = 1500;       // mm, between the posts' inner edges
constexpr double kGoalPostSeparation = kGoalInnerWidth + kGoalPostDiameter;  // mm, between the posts' centres

}  // namespace common::field
