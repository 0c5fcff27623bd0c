// Ground truth for the walk test kit's WalkMeter (include/simswift/WalkTest.hpp)
// read from a runner: the torso pose, the fall count, and per foot the middle
// of its sole and the ground's vertical force on it. Not installed: the kit
// (app/api/WalkTest.cpp), bench_motion and the motion tests feed the one
// meter through it.
#pragma once

#include <Eigen/Geometry>

#include "sim/runner/Runner.hpp"
#include "simswift/WalkTest.hpp"

namespace simswift::api {

inline WalkSample walkSample(const runner::Runner& r, int robot) {
  // The middle of the NAO's sole in the foot (AnkleRoll child) frame, m.
  static const Eigen::Vector3d kSoleCentre{0.03, 0, -0.045};
  const World& w = r.world();
  const RobotBody& body = w.robot(robot);
  WalkSample s;
  s.t = w.time();
  const RobotBody::TorsoPose t = body.torsoPose();
  s.torso.x = t.x, s.torso.y = t.y, s.torso.z = t.z, s.torso.theta = t.heading;
  s.falls = r.robotFall(robot).falls;
  const int foot[2] = {body.model().joints()[body.model().jointIndex("LAnkleRoll")].child_link,
                       body.model().joints()[body.model().jointIndex("RAnkleRoll")].child_link};
  for (const LinkContact& c : w.contacts())
    if (c.robot == robot && c.other == GeomTag::Ground)
      for (int k = 0; k < 2; ++k)
        if (c.link == foot[k]) s.feet[k].force += c.force.z();
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d p = body.linkPose(foot[k]) * kSoleCentre;
    s.feet[k].x = p.x(), s.feet[k].y = p.y();
  }
  return s;
}

}  // namespace simswift::api
