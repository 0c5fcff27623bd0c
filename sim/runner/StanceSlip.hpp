// How far a robot's stance feet slide on the carpet (a measurement for the
// motion benchmark and tests, not part of the simulation).
//
// A foot is in stance while it carries more than 70 % of the feet's ground
// force (and the feet carry more than 10 N). A stance's slip is the largest
// horizontal distance its sole centre moves from where the stance began (m).
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

#include "sim/world/World.hpp"

namespace simswift::runner {

class StanceSlip {
 public:
  explicit StanceSlip(int robot = 0) : robot_(robot) {}

  // After every tick.
  void tick(const World& w) {
    const RobotBody& r = w.robot(robot_);
    const int foot[2] = {r.model().joints()[r.model().jointIndex("LAnkleRoll")].child_link,
                         r.model().joints()[r.model().jointIndex("RAnkleRoll")].child_link};
    double fz[2] = {0, 0};  // N
    for (const LinkContact& c : w.contacts())
      if (c.robot == robot_ && c.other == GeomTag::Ground)
        for (int k = 0; k < 2; ++k)
          if (c.link == foot[k]) fz[k] += c.force.z();
    const double total = fz[0] + fz[1];
    for (int k = 0; k < 2; ++k) {
      const bool now = total > 10.0 && fz[k] > 0.7 * total;
      const Eigen::Vector3d p = r.linkPose(foot[k]) * kSoleCentre;
      if (now && !stance_[k]) {
        start_[k] = p;
        worst_[k] = 0;
      } else if (now) {
        worst_[k] = std::max(worst_[k], (p - start_[k]).head<2>().norm());
      } else if (stance_[k]) {
        per_step_.push_back(worst_[k]);
      }
      stance_[k] = now;
    }
  }
  const std::vector<double>& perStep() const { return per_step_; }  // m, one per completed stance
  double mean() const {
    double s = 0;
    for (double v : per_step_) s += v;
    return per_step_.empty() ? 0.0 : s / static_cast<double>(per_step_.size());
  }
  double max() const { return per_step_.empty() ? 0.0 : *std::max_element(per_step_.begin(), per_step_.end()); }

 private:
  // The middle of the NAO's sole in the foot (AnkleRoll child) frame (m).
  inline static const Eigen::Vector3d kSoleCentre{0.03, 0, -0.045};
  int robot_;
  bool stance_[2] = {false, false};
  Eigen::Vector3d start_[2];
  double worst_[2] = {0, 0};
  std::vector<double> per_step_;
};

}  // namespace simswift::runner
