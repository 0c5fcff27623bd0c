// The Perception thread's vision adapter and ball tracker as modules.
#pragma once

#include "agent/perception/BallTracker.hpp"
#include "agent/perception/VisionAdapter.hpp"
#include "agent/framework/Module.hpp"

namespace agent::perception {

// Motion's posture says the robot is falling, lying or getting up.
bool postureIsDown(blackboard::BodyState p);

// frame + motion (posture) -> vision.
class VisionAdapterModule
    : public framework::ModuleOf<framework::Reads<blackboard::FrameInfo, blackboard::MotionState>,
                                 framework::Writes<blackboard::VisionMeasurements>> {
 public:
  explicit VisionAdapterModule(const VisionAdapterConfig& cfg = {}) : cfg_(cfg) {}
  const char* name() const override { return "vision adapter"; }

 private:
  void update(const In& in, Out& out) override;
  VisionAdapterConfig cfg_;
};

// frame + vision + localisation + motion (odometry), team (previous frame) -> ball.
class BallTrackerModule
    : public framework::ModuleOf<framework::Reads<blackboard::FrameInfo, blackboard::VisionMeasurements,
                                                  blackboard::LocalisationEstimate, blackboard::MotionState>,
                                 framework::Writes<blackboard::BallEstimate>,
                                 framework::UsesPrevious<blackboard::TeamInfo>> {
 public:
  explicit BallTrackerModule(const BallTrackerConfig& cfg = {}) : tracker_(cfg) {}
  const char* name() const override { return "ball tracker"; }
  const BallTracker& tracker() const { return tracker_; }

 private:
  // The team ball comes from the reports team receive stored last frame.
  void update(const In& in, Out& out) override;
  BallTracker tracker_;
  bool have_odometry_ = false;
  blackboard::Odometry last_;
};

// The odometry step between two Motion odometry readings, in the robot frame
// of the first (forward mm, left mm, turn rad).
void odometryStep(const blackboard::Odometry& from, const blackboard::Odometry& to, double* forward, double* left,
                  double* turn);

}  // namespace agent::perception
