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

void VisionAdapterModule::update(const In& in, Out& out) {
  const bool down = postureIsDown(in.get<blackboard::MotionState>().posture);
  out.get<blackboard::VisionMeasurements>() = adaptVision(in.get<blackboard::FrameInfo>(), down, cfg_);
}

void BallTrackerModule::update(const In& in, Out& out) {
  const blackboard::FrameInfo& frame = in.get<blackboard::FrameInfo>();
  const blackboard::Odometry& odo = in.get<blackboard::MotionState>().odometry;
  double f = 0, l = 0, t = 0;
  if (have_odometry_) odometryStep(last_, odo, &f, &l, &t);
  last_ = odo;
  have_odometry_ = true;
  tracker_.update(frame.time, f, l, t, in.get<blackboard::VisionMeasurements>(),
                  in.get<blackboard::LocalisationEstimate>(), in.get<blackboard::TeamInfo>());
  out.get<blackboard::BallEstimate>() = tracker_.estimate();
}

}  // namespace agent::perception
