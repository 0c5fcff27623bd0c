// Localisation as a Perception module: frame + vision + motion (odometry,
// posture) + game state -> localisation.
//
// Initial poses come from the game state: when the game starts in INITIAL or
// READY, the belief starts on the own half's touch lines (robots enter from
// the sideline); it restarts at the penalty return spot when a penalty given
// during play ends (a robot penalised since the start keeps its entry belief).
// With no game, or one that starts in PLAYING (a test field, robots placed
// by hand), it starts at `known_start` when the team configured one (as on a
// test bench), otherwise anywhere in the own half.
#pragma once

#include <optional>

#include "agent/localisation/Localiser.hpp"
#include "agent/framework/Module.hpp"

namespace agent::localisation {

struct LocalisationModuleConfig {
  LocaliserConfig filter;
  std::optional<blackboard::FieldPose> known_start;  // mm, rad; field frame
};

class LocalisationModule
    : public framework::ModuleOf<framework::Reads<blackboard::FrameInfo, blackboard::VisionMeasurements,
                                                  blackboard::MotionState, blackboard::GameInfo>,
                                 framework::Writes<blackboard::LocalisationEstimate>> {
 public:
  explicit LocalisationModule(const LocalisationModuleConfig& cfg = {}) : cfg_(cfg), filter_(cfg.filter) {}
  const char* name() const override { return "localisation"; }
  const Localiser& filter() const { return filter_; }

 private:
  void update(const In& in, Out& out) override;
  LocalisationModuleConfig cfg_;
  Localiser filter_;
  bool started_ = false;
  bool was_penalised_ = false;
  bool has_played_ = false;  // was in PLAYING, unpenalised, at some frame
  blackboard::Odometry last_;
};

}  // namespace agent::localisation
