// Every weight, rate and threshold of the behaviour in one typed struct,
// with defaults and units. A scenario may override any field (the YAML
// loader lives sim-side); the robot code only ever sees this struct.
// Units: mm, mm/s, rad, rad/s, s; probabilities are unitless.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "agent/behaviour/Geometry.hpp"
#include "common/field/FieldFacts.hpp"
#include "common/nao/NaoFacts.hpp"

namespace agent::behaviour {

// Field geometry the behaviour plans with (SPL 2017, common/field/FieldFacts.hpp).
struct FieldGeometry {
  double length = common::field::kLength;  // mm, goal line to goal line
  double width = common::field::kWidth;    // mm, touch line to touch line
  double goal_post_y = common::field::kGoalPostSeparation / 2;     // mm, post centres at x = +-length/2, y = +-goal_post_y
  double goal_post_radius = common::field::kGoalPostDiameter / 2;  // mm
};

// PositionalDistribution's grid (thesis 4.2.1).
struct GridConfig {
  int columns = 3;  // segments along x (3 x 3 gives table 4.1's centres)
  int rows = 3;     // segments along y
  // If true, columns/rows are ignored and the smallest grid is chosen whose
  // segments' centre-to-corner distance is at most
  // reliable_detection_distance - detection_margin (thesis 4.2.1).
  bool derive_from_detection = false;
  double reliable_detection_distance = 2500.0;  // mm (thesis chapter 5)
  double detection_margin = 200.0;              // mm kept back for estimation error
};

// CompositeDistributionGenerator's components (thesis 4.2.1.1). Rates are
// per second so the result does not depend on the behaviour's tick rate.
struct DistributionConfig {
  // BallPosComponent: probability mass added to the ball's segment per second
  // of sighting (before normalisation).
  double ball_pos_rate = 5.0;  // 1/s
  // EntropyComponent: each segment moves toward 1/J by the fraction
  // 1 - exp(-entropy_rate * dt) per update.
  double entropy_rate = 0.01;  // 1/s (time constant 100 s)
  // RobotPosComponent: the robot's own segment is multiplied by
  // exp(-robot_pos_rate * dt) per update while the ball is not seen.
  double robot_pos_rate = 0.3;  // 1/s
  // FlipFilterComponent: reset on the flip signal, or when the pose
  // confidence falls below this (0 disables the confidence test).
  double flip_min_confidence = 0.0;  // 0..1
};

// Strategy (thesis 4.2.2).
struct StrategyConfig {
  bool distributed = true;  // DistributedUtilityCalculator over SimpleUtilityCalculator
  // Time(pos, centre) never goes below this, so a robot standing on a
  // segment's centre does not get an infinite utility.
  double min_travel_time = 1.0;  // s
  // Teammates heard longer ago than this are ignored (their distribution
  // and their chosen segment).
  double teammate_timeout = 2.0;  // s
  // Within this distance of the centre the turn to face it is not counted.
  double face_distance = 300.0;  // mm
  // One searcher per segment (thesis 4.2.2.2 gives the reason: robots heading
  // to one place "may collide with each other, possibly causing robots to
  // fall over"). A segment a teammate has chosen is left to it (utility 0
  // here) if the teammate is nearer its centre than this robot (ties: the
  // lower player number keeps it); the division by visitors stays for the
  // rest. Both robots judge with the same rule from the same packets, so the
  // farther one yields. false: the thesis's formula alone.
  bool exclusive_segments = true;
};

// The FindBall behaviours (2017 thesis 4.2.3 and 2016 thesis 2.3.2).
struct SearchBehaviourConfig {
  double arrive_distance = 300.0;  // mm: at the search point
  bool scan_at_point = true;       // head scan on arrival
  bool spin_at_point = true;       // then one full turn
  bool scan_while_walking = true;  // head sweeps while walking between points
  // 2017: while walking, switch to a new suggestion only if its utility is
  // this many times the current target's (1 = always follow, large = latch).
  double switch_hysteresis = 1.5;
  // 2016 FindBall: table 2.1's points (field frame, mm).
  std::vector<Point2> points_2016{{-3000, 0},  {-2000, 2000}, {0, 1000},   {2000, 2000},
                                  {3000, 0},   {2000, -2000}, {0, -1000},  {-2000, -2000}};
};

// The 2016 FindBall's manner (thesis 2.3.2 gives the points and their order
// only). The 2016 FindBall itself was never released.
enum class Search2016Style : int32_t {
  // As the era's robots did: walk through the points without stopping
  // (switch to the next point within pass_distance), the head as `head`
  // below says. The default.
  ERA = 0,
  // At every point: stop, head scan, spin, as the 2017 behaviour does at
  // its points (SearchBehaviourConfig's flags; the earlier simswift variant).
  STOP_SCAN_SPIN,
};
enum class Search2016Head : int32_t {
  // rUNSWift 2016 release, skills/HeadSkill.py (the default head skill): with
  // the ball lost the head yaws toward the ball estimate (atan2 of its
  // neck-relative position), pitch 17 deg within 800 mm (hysteresis 0.9 /
  // 1.1), 0 deg beyond; yaw speed 0.25 and pitch speed 0.2 of the head's
  // maximum.
  BALL_ESTIMATE = 0,
  // The HeadScan sweep while walking (SkillConfig's scan_*). The default:
  // the 2016 FindBall was a behaviour of its own and may have overridden the
  // head skill (its code is not public); the thesis describes its search
  // by what is visible round each point and along the routes (2.3.2,
  // figures 2.10-2.12), which a head fixed on a never-seen ball's estimate
  // (the field centre) does not see: with BALL_ESTIMATE the thesis's
  // simulated experiment finds 10 of 100 balls (seed 2017 file, 2026-11-25;
  // docs/experiment.md), against 80/100 in the thesis's simulation and 20/25
  // on its real NAOs. A coarse inconsistency, not a fit: no number is tuned.
  SCAN,
};
struct Search2016Config {
  Search2016Style style = Search2016Style::ERA;
  Search2016Head head = Search2016Head::SCAN;
  // mm: in era style, within this of a point the next one is the target.
  // rUNSWift 2016 release, skills/WalkToPointV2.py: 400 mm is where its walk
  // leaves travel (FarAway) for the final approach (Nearby); passing a point
  // needs no final approach.
  double pass_distance = 400.0;
  // The era's head skill (HeadSkill.py above), rad and rad/s. Its speeds are
  // fractions of the head's top speed, about 3.85 deg per 10 ms motion cycle
  // (6.72 rad/s): 0.25 -> 1.68 rad/s yaw, 0.2 -> 1.34 rad/s pitch.
  double head_near_pitch = 0.2967;     // rad (17 deg), ball estimate nearer than head_near_distance
  double head_far_pitch = 0.0;         // rad
  double head_near_distance = 800.0;   // mm (switch at 0.9x / 1.1x)
  double head_yaw_speed = 1.68;        // rad/s
  double head_pitch_speed = 1.34;      // rad/s
};

// Skills.
struct SkillConfig {
  // WalkTo
  double walk_gain = 1.5;             // 1/s: speed = gain * distance near the target
  double turn_gain = 1.5;             // 1/s: turn rate = gain * heading error
  double face_target_distance = 500;  // mm: beyond it, face the direction of travel
  double final_angle_tolerance = 0.15;  // rad
  double translate_max_heading_error = 1.0;  // rad: beyond it, turn on the spot first
  double robot_radius = common::nao::kFootprintRadius;  // mm, for avoidance: the robot's own footprint
  double avoid_distance = 600.0;      // mm: obstacles further (surface to surface) are ignored
  double avoid_gain = 60000.0;        // mm^2/s: repulsion = gain * (1/d - 1/avoid_distance)
  double obstacle_timeout = 2.0;      // s: teammates heard longer ago are not avoided
  // Keep-out round teammates (as heard: team packets, 5 Hz, their own
  // localisation): within keep_out_distance (mm, centre to centre) of a
  // teammate the part of the walk command that closes on it is removed, so
  // two robots never walk into each other whatever their targets. A target
  // a nearer teammate is standing on counts as reached within
  // blocked_arrive_distance (mm) (the robot searches from beside it).
  // rUNSWift 2016 release, skills/WalkToPointV2.py avoided the robots it
  // knew of (a potential field, 800 mm reach); this keeps that and adds
  // the hard limit.
  double keep_out_distance = 550.0;   // mm: two 150 mm radii plus 250 mm for localisation error
  double blocked_arrive_distance = 900.0;  // mm
  // Sonar avoidance: what the chest sonars report close by is avoided like a
  // teammate (keep-out, repulsion, a target it is nearer to counts as
  // reached within blocked_arrive_distance), whatever the team packets say.
  // This catches a teammate whose packets put it elsewhere (a robot whose
  // localisation took the field's mirror twin walked into one standing on
  // its target, docs/experiment.md). The era's rule: rUNSWift 2016 release,
  // util/Sonar.py counts a side as having a nearby object while its first
  // echo reads under 0.4 m, after 3 such frames and for 10 frames after the
  // last, and skills/WalkToPointV2.py then avoids an obstacle
  // Constants.ROBOT_DIAM (450 mm) away, 30 deg to that side.
  bool sonar_avoid = true;
  double sonar_near_distance = 400.0;     // mm: a first echo under this is near
  double sonar_min_frames = 3;            // behaviour frames of near echoes before a side counts
  double sonar_hold_frames = 10;          // behaviour frames a side still counts after the last
  double sonar_obstacle_distance = 450.0; // mm, robot centre to the assumed obstacle centre
  double sonar_obstacle_angle = 0.5236;   // rad (30 deg) off straight ahead, to the side that heard it
  // Ours, not the era's: while a side counts as near the robot also steps
  // back from it at sonar_back_off_speed without turning (so it never stops
  // within a turning robot's reach), and a target within
  // blocked_arrive_distance counts as reached only once no side counts as
  // near, with an echo (any, within the sonar's range) in front nearer the
  // target than the robot (the one standing on the target is left to it).
  double sonar_back_off_speed = 100.0;    // mm/s
  // Passing an oncoming teammate: one whose heading is within 60 deg of
  // the opposite of this robot's, ahead by up to pass_lookahead (mm along
  // the pair's axis, and no further than the target plus two robot radii)
  // and less than pass_clearance (mm) to either side of that axis, is
  // passed on the left: the way bends right by the angle that brings the
  // teammate pass_clearance to the left by the time it is alongside, at
  // most pass_max_steer (rad). One clearly to the right (more than
  // robot_radius) is passed on the right the same way. The axis is the
  // mean of the two headings, so both robots of a pair measure the same
  // side and always choose the same way round. Without it: the repulsion
  // pushes both the same way when their paths cross at a shallow angle,
  // and the keep-out stops them too late at walking speed (the walk sheds
  // WalkConfig::ratchet_forward a step), nose to nose
  // (thesis_findball.yaml trial 125, docs/experiment.md).
  // The era steered rather than stopped: rUNSWift 2016 release,
  // skills/WalkToPointV2.py turned the way by the potential field, for
  // obstacles within 1 m of the path ahead, by at most 70 deg. The side
  // convention is ours. Keep pass_max_steer below
  // translate_max_heading_error, so the robot bends its way without
  // stopping to turn. keep_right: false turns the rule off (as before).
  bool keep_right = true;
  double pass_lookahead = 1500.0;  // mm
  double pass_clearance = 500.0;  // mm: two 150 mm radii plus 200 mm
  double pass_max_steer = 0.785;  // rad (45 deg)
  // HeadScan. The stop at a 2017 search point (thesis 4.2.3: "scans the
  // robot head ... Failing to find the ball, ... spins the robot around";
  // neither how far nor how fast is said, and the code is not public):
  //  - scan_yaw: the sweep takes the camera's edge to +-90 deg, the robot's
  //    front half: pi/2 - camera_hfov/2 = 1.04 rad.
  //  - scan_speed: 1.68 rad/s, the speed the era's head skill moved the head
  //    at with the ball lost (rUNSWift 2016 and 2018 releases,
  //    skills/HeadSkill.py: 0.25 of the head's 6.72 rad/s). One sweep
  //    4 x 1.04 / 1.68 = 2.5 s; a ball stays in view for 1.06 / 1.68 = 0.63 s,
  //    19 frames at 30 Hz.
  //  - spin_speed: the era's walk turn limit, 0.8 rad/s (rUNSWift 2016
  //    release, Walk2014Generator); its behaviours' travel-time estimate
  //    assumed 60 deg/s (1.05 rad/s, util/FieldGeometry.py), above what the
  //    walk could do, so the walk's limit it is.
  //  - spin_angle: turn until every direction has been in view: after the
  //    scan the front +-(scan_yaw + hfov/2) has been seen, so the turn (head
  //    ahead) must reach 2 pi - scan_yaw - camera_hfov = 4.18 rad (240 deg);
  //    2.5 s of scan plus 5.2 s of turn. spin_angle <= 0 means that value;
  //    2 pi is a whole turn (the earlier simswift choice).
  double scan_yaw = 1.04;          // rad, sweep between -scan_yaw and +scan_yaw
  double scan_speed = 1.68;        // rad/s (HeadYaw can do 8.27 rad/s)
  double scan_pitch = 0.05;        // rad, + = down
  double head_yaw_limit = 2.0;     // rad, kept inside HeadYaw's +-2.0857
  double head_speed_limit = 8.0;   // rad/s, inside HeadYaw's 8.27 rad/s
  // rad; unset: the lens of the body the program drives, which the robot
  // program sets at start (a V5's 60.9 deg, a V6's 56.3 deg: NaoFacts.hpp).
  std::optional<double> camera_hfov;
  double cameraHfov() const {  // the V5's where no program has set it (tests, tools)
    return camera_hfov.value_or(common::nao::kV5CameraLens.horizontal_fov);
  }
  double scan_lead = 1.25;         // head speed command / sweep speed (keeps up with the target)
  double head_pitch_speed = 1.0;   // rad/s while scanning
  // Looking at a ball: pitch = atan(head_height / distance) - look_pitch_offset,
  // clamped to 0 .. look_max_pitch (the top camera looks 1.2 deg down, the
  // bottom one 39.7 deg, so the ball stays in one of them).
  double head_height = 450.0;      // mm, camera above the ground (standing)
  double look_pitch_offset = 0.2;  // rad
  double look_max_pitch = 0.45;    // rad
  double look_yaw_speed = 3.0;     // rad/s
  double look_pitch_speed = 2.0;   // rad/s
  // Spin (see HeadScan above for the choice)
  double spin_speed = 0.8;         // rad/s (clamped to the walk's max_turn)
  double spin_angle = 0.0;         // rad of turn; <= 0: 2 pi - scan_yaw - camera_hfov
  // ApproachBall / Kick
  double approach_distance = 180.0;   // mm, robot centre to ball centre when lined up
  double approach_tolerance = 60.0;   // mm
  double kick_angle_tolerance = 0.2;  // rad
  double kick_duration = 2.0;         // s the kick request is held
  double kick_power = 1.0;            // 0..1
  double ball_lost_time = 3.0;        // s without a sighting before the ball counts as lost
  double team_ball_max_age = 2.0;     // s: a teammate's sighting older than this is ignored
  Point2 kick_target{common::field::kLength / 2, 0};  // mm, opponent goal centre
  // Strikers of one team: the one nearest the ball plays it (by this
  // robot's ball and its teammates' heard poses), by more than role_margin;
  // within it, the lower player number does, so two robots closing in do
  // not swap every packet. The others wait support_distance behind the
  // ball toward their own goal, facing it.
  bool team_roles = true;
  double role_margin = 300.0;        // mm
  double support_distance = 1200.0;  // mm
};

enum class BehaviourKind : int32_t { FINDBALL_2016 = 0, FINDBALL_2017, STRIKER };

// The behaviour kinds, one row each: the kind and its name, as a scenario's,
// an experiment's and a robot setup's `behaviour:` and simswift-agent
// --behaviour spell it. Every list of kinds (the readers' choices, their
// error messages, the help, the FindBall view's captions) is read from here.
// Row i is kind i (FindBallInfo::kind carries the number).
struct BehaviourKindRow {
  BehaviourKind kind;
  const char* name;
};
inline constexpr BehaviourKindRow kBehaviourKinds[] = {
    {BehaviourKind::FINDBALL_2016, "findball2016"},
    {BehaviourKind::FINDBALL_2017, "findball2017"},
    {BehaviourKind::STRIKER, "striker"},
};
constexpr int kNumBehaviourKinds = static_cast<int>(sizeof kBehaviourKinds / sizeof kBehaviourKinds[0]);
constexpr bool behaviourKindRowsInOrder() {
  for (int i = 0; i < kNumBehaviourKinds; ++i)
    if (static_cast<int>(kBehaviourKinds[i].kind) != i) return false;
  return true;
}
static_assert(behaviourKindRowsInOrder(), "kBehaviourKinds: row i must be kind i");

// The `behaviour:` that runs no behaviour: the robot's actions: list.
inline constexpr const char* kScriptBehaviourName = "script";

// The kind's name; "?" for a number outside the table.
inline const char* behaviourKindName(BehaviourKind k) {
  const int i = static_cast<int>(k);
  return i >= 0 && i < kNumBehaviourKinds ? kBehaviourKinds[i].name : "?";
}
// False (kind untouched) for an unknown name, so a loader can report it.
inline bool parseBehaviourKind(const std::string& name, BehaviourKind* kind) {
  for (const BehaviourKindRow& r : kBehaviourKinds)
    if (name == r.name) {
      *kind = r.kind;
      return true;
    }
  return false;
}
// Every name a `behaviour:` may take: the kinds in the table's order, then
// kScriptBehaviourName.
inline const std::vector<std::string>& behaviourNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const BehaviourKindRow& r : kBehaviourKinds) v.push_back(r.name);
    v.push_back(kScriptBehaviourName);
    return v;
  }();
  return names;
}
// The same for messages and help: "findball2016, findball2017, striker or script".
inline std::string behaviourNamesText() {
  const std::vector<std::string>& v = behaviourNames();
  std::string t;
  for (size_t i = 0; i < v.size(); ++i) t += (i == 0 ? "" : i + 1 == v.size() ? " or " : ", ") + v[i];
  return t;
}

struct BehaviourConfig {
  BehaviourKind kind = BehaviourKind::FINDBALL_2017;
  FieldGeometry field;
  GridConfig grid;
  DistributionConfig distribution;
  StrategyConfig strategy;
  SearchBehaviourConfig search;
  Search2016Config search2016;
  SkillConfig skills;
};

}  // namespace agent::behaviour
