// The Perception thread's vision adapter and ball tracker as modules.
#pragma once

#include "agent/perception/BallTracker.hpp"
#include "agent/perception/VisionAdapter.hpp"
#include "agent/program/Module.hpp"

namespace agent::perception {

// Motion's posture says the robot is falling, lying or getting up.
bool postureIsDown(blackboard::BodyState p);

// frame + motion (posture) -> vision.
class VisionAdapterModule : public program::Module {
 public:
  explicit VisionAdapterModule(const VisionAdapterConfig& cfg = {}) : cfg_(cfg) {}
  const char* name() const override { return "vision adapter"; }
  std::vector<program::SectionId> reads() const override {
    return {program::SectionId::Frame, program::SectionId::Motion};
  }
  std::vector<program::SectionId> writes() const override { return {program::SectionId::Vision}; }
  void run(blackboard::Blackboard& board) override;

 private:
  VisionAdapterConfig cfg_;
};

// frame + vision + localisation + motion (odometry), team (previous frame) -> ball.
class BallTrackerModule : public program::Module {
 public:
  explicit BallTrackerModule(const BallTrackerConfig& cfg = {}) : tracker_(cfg) {}
  const char* name() const override { return "ball tracker"; }
  std::vector<program::SectionId> reads() const override {
    using S = program::SectionId;
    return {S::Frame, S::Vision, S::Localisation, S::Motion};
  }
  std::vector<program::SectionId> writes() const override { return {program::SectionId::Ball}; }
  // The team ball comes from the reports team receive stored last frame.
  std::vector<program::SectionId> usesPrevious() const override { return {program::SectionId::Team}; }
  void run(blackboard::Blackboard& board) override;
  const BallTracker& tracker() const { return tracker_; }

 private:
  BallTracker tracker_;
  bool have_odometry_ = false;
  blackboard::Odometry last_;
};

// The odometry step between two Motion odometry readings, in the robot frame
// of the first (forward mm, left mm, turn rad).
void odometryStep(const blackboard::Odometry& from, const blackboard::Odometry& to, double* forward, double* left,
                  double* turn);

}  // namespace agent::perception
