// Named whole-body postures in libagent joint order (angles rad, stiffness
// 0..1). Used by the robot program to hold a pose, by scenarios to place a
// robot, and by the body side's safe sit when contact is lost: a fact of the
// NAO both sides share, so it lives in the foundation (common/nao).
//
// stand:  knees bent (HipPitch -0.4, KneePitch 0.8, AnklePitch -0.4 rad) so
//         the torso stays upright over the feet (hip + knee + ankle = 0) and
//         the knees have room to absorb; arms hang beside the body.
// crouch: deeper (HipPitch -0.8, KneePitch 1.6, AnklePitch -0.8 rad), the
//         safe low posture; still feet flat, torso upright.
// limp:   the stand angles with stiffness 0: the robot collapses.
// zero:   every joint at 0 rad (straight legs, arms forward), stiffness 1.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/libagent/AgentShared.hpp"

namespace common::nao {

enum class Posture { Stand, Crouch, Limp, Zero };

using JointArray = std::array<float, common::libagent::kNumJoints>;

JointArray postureAngles(Posture p);       // rad
float postureStiffness(Posture p);         // 0..1, the same for every joint
const char* postureName(Posture p);
const std::vector<std::string>& postureNames();  // the names files use, in enum order
std::optional<Posture> parsePosture(const std::string& name);  // "stand", ...

// Fills a JointValues (angles, stiffnesses; temperatures/currents 0).
common::libagent::JointValues postureCommand(Posture p);

// libagent index of a NAO joint name ("HeadYaw"), -1 if unknown.
int jointIndex(const std::string& name);

}  // namespace common::nao
