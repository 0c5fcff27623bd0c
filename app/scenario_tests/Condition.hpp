// A scenario test's pass condition: state predicates over the world's truth
// (Truth.hpp), combined with all / any / not, inside temporal operators
// that say when they must hold:
//
//   pass:
//     all:
//       - within: {seconds: 60, that: {ball_in_goal: red}}   # at some tick <= 60 s
//       - never: {fallen: any}                                # at no tick
//       - always: {not: {robots_within: 0.2}}                 # at every tick
//       - at_end: {ball_in_zone: {x: [0, 4.5], y: [-3, 3]}}  # at the time limit
//       - eventually: {near_ball: {robot: 0, distance: 0.3}}  # within the time limit
//
// State predicates (robot: a scenario index, `any`, `blue` or `red`):
//   ball_in_goal: blue | red | any      the whole ball over that side's goal line
//                                       between the posts (blue defends -x)
//   ball_in_zone: {x: [lo, hi], y: [lo, hi]}           m, field frame
//   near_ball: {robot, distance, count: 1}   at least `count` of the robots
//                                       within `distance` m of the ball (torso, ground)
//   near_pose: {robot, x, y, distance}  a robot within distance m of (x, y)
//   fallen: ROBOT                       a robot is down now (torso below the fall height)
//   falls: {robot, at_least: N}         the robots' falls so far, summed, >= N
//   penalised: ROBOT                    a robot is penalised now
//   touched_ball: ROBOT                 a robot has touched the ball so far
//   game_state: initial|ready|set|playing|finished
//   team_packets: {team: blue|red, at_most: N}   packets the team sent so far
//   time: {at_least: S}                 s since the start
//   robots_within: D                    two robots' torsos closer than D m (ground)
//
// The run ends at the time limit, or as soon as the condition is decided:
// failed for good, or (when it has an eventually / within) met, with every
// always / never on a path of `all`s from the root counted as holding so
// far. So an invariant is checked until the goal is reached, not after:
// `all: [{within: {seconds: 60, that: {touched_ball: 0}}}, {never:
// {ball_in_goal: blue}}]` ends at the first touch; to watch for an own goal
// over the whole minute, ask `at_end: {touched_ball: 0}` instead. A test
// with only invariants and at_end runs to its time limit.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/config/YamlReader.hpp"
#include "app/scenario_tests/Truth.hpp"

namespace simswift::scenario_tests {

// A state predicate or all / any / not of them: true or false at one tick.
struct StateNode {
  enum class Kind {
    All, Any, Not,
    BallInGoal, BallInZone, NearBall, NearPose, Fallen, Falls, Penalised, TouchedBall, GameState,
    TeamPackets, Time, RobotsWithin
  } kind = Kind::All;
  std::vector<StateNode> children;  // All, Any, Not (one)
  // Robot selector: >= 0 a scenario index; kAny, kBlue, kRed.
  static constexpr int kAny = -1, kBlue = -2, kRed = -3;
  int robot = kAny;
  int side = -1;                     // BallInGoal, TeamPackets: 0 blue, 1 red, -1 any
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // BallInZone (m); NearPose: (x0, y0)
  double distance = 0;               // m
  int64_t count = 1;                 // NearBall: robots; Falls: at_least; TeamPackets: at_most
  double seconds = 0;                // Time: at_least
  common::libagent::GameStateValue state = common::libagent::GameStateValue::Playing;
  std::string text;                  // as written, for messages ("fallen: any")

  bool eval(const Truth& t, const FieldConfig& f) const;
};

enum class Verdict3 { Pending, True, False };

// A temporal operator over a state node, or all / any / not of temporal nodes.
struct TimeNode {
  enum class Kind { All, Any, Not, Within, Always, AtEnd } kind = Kind::All;
  std::vector<TimeNode> children;    // All, Any, Not (one)
  StateNode that;                    // Within, Always, AtEnd
  double seconds = 0;                // Within: the deadline (s); eventually = the time limit
  bool negate = false;               // Always of `never:` (holds while `that` is false)
  std::string text;                  // as written
};

// Reads `pass:` (a map of one operator). ConfigError with file:line:key for
// a misspelt or misplaced operator ("did you mean"), a state predicate
// outside a temporal operator, a robot the scenario lacks, bad ranges.
// time_limit: s (within's seconds must not exceed it).
TimeNode readCondition(const common::config::YamlReader& parent, const std::string& key, int num_robots,
                       double time_limit);

bool hasEventually(const TimeNode& n);

// The condition's evaluation over one run, tick by tick.
class ConditionRun {
 public:
  explicit ConditionRun(const TimeNode& root, const FieldConfig& field);
  // After each tick. Returns the verdict so far (True: met, the run may stop).
  Verdict3 update(const Truth& t);
  // At the time limit: pending nodes resolve (eventually false, always true,
  // at_end evaluated on `t`).
  Verdict3 finish(const Truth& t);
  // After a False verdict: the first temporal operator that failed, and when (s).
  std::string failure() const { return failure_; }
  double failureTime() const { return failure_t_; }
  // When the verdict was decided (s).
  double decidedAt() const { return decided_t_; }

 private:
  struct State {
    Verdict3 v = Verdict3::Pending;
    double t = 0;  // when decided
  };
  void advance(const TimeNode& n, size_t& id, const Truth& t, bool at_end);
  Verdict3 value(const TimeNode& n, size_t& id, bool optimistic);
  void firstFailure(const TimeNode& n, size_t& id, bool positive);
  Verdict3 decide(const Truth& t, bool at_end);

  const TimeNode& root_;
  const FieldConfig& field_;
  std::vector<State> states_;  // one per node, pre-order
  std::string failure_;
  double failure_t_ = 0, decided_t_ = 0;
  bool can_stop_early_ = false;
};

}  // namespace simswift::scenario_tests
