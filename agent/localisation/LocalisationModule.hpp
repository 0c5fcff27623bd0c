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
#include "agent/program/Module.hpp"

namespace agent::localisation {

struct LocalisationModuleConfig {
  LocaliserConfig filter;
  std::optional<blackboard::FieldPose> known_start;  // mm, rad; field frame
};

class LocalisationModule : public program::Module {
 public:
  explicit LocalisationModule(const LocalisationModuleConfig& cfg = {}) : cfg_(cfg), filter_(cfg.filter) {}
  const char* name() const override { return "localisation"; }
  std::vector<program::SectionId> reads() const override {
    using S = program::SectionId;
    return {S::Frame, S::Vision, S::Motion, S::GameState};
  }
  std::vector<program::SectionId> writes() const override { return {program::SectionId::Localisation}; }
  void run(blackboard::Blackboard& board) override;
  const Localiser& filter() const { return filter_; }

 private:
  LocalisationModuleConfig cfg_;
  Localiser filter_;
  bool started_ = false;
  bool was_penalised_ = false;
  bool has_played_ = false;  // was in PLAYING, unpenalised, at some frame
  blackboard::Odometry last_;
};

}  // namespace agent::localisation
