#include "agent/localisation/LocalisationModule.hpp"

#include "agent/perception/PerceptionModules.hpp"

namespace agent::localisation {

void LocalisationModule::update(const In& in, Out& out) {
  const blackboard::FrameInfo& frame = in.get<blackboard::FrameInfo>();
  const blackboard::MotionState& motion = in.get<blackboard::MotionState>();
  const blackboard::GameInfo& game = in.get<blackboard::GameInfo>();
  double f = 0, l = 0, t = 0;
  if (!started_) {
    // Robots walk in from the sideline at the start of a game; a game that
    // starts in PLAYING is a test field with robots placed by hand.
    if (game.known && (game.state == blackboard::GameStateId::INITIAL || game.state == blackboard::GameStateId::READY))
      filter_.reset(InitialPose::SidelineEntry);
    else if (cfg_.known_start)
      filter_.resetTo(*cfg_.known_start, 50, 0.05);
    else
      filter_.reset(InitialPose::OwnHalf);
    started_ = true;
  } else {
    perception::odometryStep(last_, motion.odometry, &f, &l, &t);
  }
  last_ = motion.odometry;
  // A robot penalised while playing is carried off and put back at the
  // penalty return spot. One penalised before it ever played (in INITIAL,
  // as at the start of a test) stays where it entered: its sideline-entry
  // belief still holds, so it is kept.
  if (was_penalised_ && !game.penalised && has_played_) filter_.reset(InitialPose::PenaltyReturn);
  was_penalised_ = game.penalised;
  if (game.state == blackboard::GameStateId::PLAYING && !game.penalised) has_played_ = true;
  filter_.update(f, l, t, in.get<blackboard::VisionMeasurements>(), frame.time,
                 game.penalised || perception::postureIsDown(motion.posture));
  out.get<blackboard::LocalisationEstimate>() = filter_.estimate();
}

}  // namespace agent::localisation
