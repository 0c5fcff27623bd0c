#include "agent/perception/PerceptionModules.hpp"

#include <cmath>

namespace agent::perception {

using blackboard::BodyState;

bool postureIsDown(BodyState p) {
  return p == BodyState::FALLING || p == BodyState::FALLEN_FORWARD || p == BodyState::FALLEN_BACKWARD ||
         p == BodyState::FALLEN_SIDEWAYS || p == BodyState::GETTING_UP;
}

void odometryStep(const blackboard::Odometry& from, const blackboard::Odometry& to, double* forward, double* left,
                  double* turn) {
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  *forward = c * dx + s * dy;
  *left = -s * dx + c * dy;
  *turn = to.theta - from.theta;
}

void VisionAdapterModule::run(blackboard::Blackboard& board) {
  const blackboard::FrameInfo frame = board.frame.read();
  const bool down = postureIsDown(board.motion.read().posture);
  board.vision.write(adaptVision(frame, down, cfg_));
}

void BallTrackerModule::run(blackboard::Blackboard& board) {
  const blackboard::FrameInfo frame = board.frame.read();
  const blackboard::Odometry odo = board.motion.read().odometry;
  double f = 0, l = 0, t = 0;
  if (have_odometry_) odometryStep(last_, odo, &f, &l, &t);
  last_ = odo;
  have_odometry_ = true;
  tracker_.update(frame.time, f, l, t, board.vision.read(), board.localisation.read(), board.team.read());
  board.ball.write(tracker_.estimate());
}

}  // namespace agent::perception
