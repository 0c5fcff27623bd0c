// Roles on top of the skills.
//   Searcher: FindBall (2016 or 2017) until this robot or a teammate sees
//     the ball; then walks up to the ball (approach_distance) watching it.
//   Striker: ApproachBall then Kick while the ball is known and this robot
//     plays it (the nearest of its team's strikers: SkillConfig::team_roles);
//     a striker that does not waits behind the ball; FindBall 2017 while the
//     ball is unknown. Shows the stack end to end.
#pragma once

#include <optional>

#include "agent/behaviour/ApproachBall.hpp"
#include "agent/behaviour/FindBall2016.hpp"
#include "agent/behaviour/FindBallBehaviour.hpp"
#include "agent/behaviour/Kick.hpp"

namespace agent::behaviour {

struct RoleOutput {
  blackboard::BodyCommand body;
  blackboard::HeadCommand head;
  const char* activity = "";  // short description, for logs and views
  bool searching = false;     // the FindBall behaviour is driving
};

// The ball this robot should act on: its own estimate if seen within
// ball_lost_time, else the team ball if fresher than team_ball_max_age.
std::optional<Point2> knownBall(const BehaviourInputs& in, const SkillConfig& s);

class Searcher {
 public:
  Searcher(const BehaviourConfig& c, bool use_2017)
      : c_(c), use_2017_(use_2017), fb2017_(c), fb2016_(c), walk_(c.skills, c.field) {}
  void reset() {
    fb2017_.reset();
    fb2016_.reset();
  }
  // fb: this tick's FindBall class result (needed for 2017).
  RoleOutput tick(const BehaviourInputs& in, const FindBallResult* fb);
  const FindBallBehaviour& findBall2017() const { return fb2017_; }
  const FindBall2016& findBall2016() const { return fb2016_; }

 private:
  BehaviourConfig c_;
  bool use_2017_;
  FindBallBehaviour fb2017_;
  FindBall2016 fb2016_;
  WalkTo walk_;
};

class Striker {
 public:
  explicit Striker(const BehaviourConfig& c)
      : c_(c), approach_(c.skills, c.field), kick_(c.skills), search_(c, true) {}
  void reset() {
    kicking_ = false;
    search_.reset();
  }
  RoleOutput tick(const BehaviourInputs& in, const FindBallResult* fb);
  const Searcher& searcher() const { return search_; }

 private:
  // Whether this robot plays the ball (team_roles).
  bool playsBall(const BehaviourInputs& in, Point2 ball);

  BehaviourConfig c_;
  WalkTo support_{c_.skills, c_.field};
  ApproachBall approach_;
  Kick kick_;
  Searcher search_;
  bool kicking_ = false;
};

}  // namespace agent::behaviour
