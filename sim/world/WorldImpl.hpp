// World internals shared by World.cpp, Contacts.cpp, FieldGeometry.cpp and
// StateHash.cpp. Not part of the public contract: include World.hpp instead.
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <memory>
#include <vector>

#include "sim/world/World.hpp"

namespace simswift {

// A contact found by collision, before its joint is made.
struct ContactCandidate {
  dContactGeom geom;   // as dCollide returned it (normal pushes g1's body out)
  GeomTag a, b;        // tags of geom.g1 and geom.g2
  int sole_point = -1; // for a sole grid point on the ground: its index in the grid
};

struct World::Impl {
  // Static field geoms (ground, posts, crossbars, nets): their own simple
  // space inside the world space, so static-static pairs are never tested.
  dSpaceID static_space = nullptr;
  std::vector<std::unique_ptr<GeomTag>> static_tags;

  // The ball.
  dBodyID ball = nullptr;
  dGeomID ball_geom = nullptr;
  GeomTag ball_tag{GeomTag::Ball, -1, -1};
  Eigen::Vector3d ball_placed = Eigen::Vector3d::Zero();  // last placeBall (m, field)
  bool ball_removed = false;  // removeBall(): scenario `ball: none`

  // Robots: one simple space each (own-link pairs are never tested), the
  // model kept alive, and where each was last placed (for blow-up resets).
  struct Placement {
    double x = 0, y = 0, theta = 0;  // m, m, rad (field frame)
    std::vector<double> posture;     // rad, model joint order
  };
  std::vector<dSpaceID> robot_spaces;
  std::vector<std::shared_ptr<const RobotModel>> models;
  std::vector<Placement> placements;
  // Pushes waiting for the next step (N*s, world frame), per robot.
  std::vector<Eigen::Vector3d> pending_impulse;

  // Contacts of the current substep.
  dJointGroupID contact_group = nullptr;
  std::vector<ContactCandidate> candidates;
  // Feedback for contacts touching a robot link: which robot/link, and
  // whether it is the contact joint's first body (f1) or second (f2).
  struct Feedback {
    int robot, link;
    GeomTag::Kind other;
    int other_robot;
    bool first;
    size_t slot;  // index into feedback
    Eigen::Vector3d position;
    bool sole;    // a point of a sole's patch on the ground
  };
  std::vector<dJointFeedback> feedback;
  std::vector<Feedback> feedback_meta;

  // Sole points in contact with the ground: where each touched down (m,
  // world xy), keyed by (robot, link, grid point). Rebuilt every substep
  // from the contacts; a point that lifts off is forgotten.
  std::map<std::array<int, 3>, Eigen::Vector2d> sole_anchors;

  // Scratch: which links of one robot touch the ground (World::projectJoints).
  std::vector<char> pinned;

  // Reused ray for rayCast (not in any space).
  dGeomID ray = nullptr;

  // FieldGeometry.cpp: ground, goals and nets for `field`.
  void buildField(const FieldConfig& field);
  // Contacts.cpp: collides everything, creates the contact joints for a
  // substep of `dt` s (sorted, so the order never depends on memory).
  void collide(dWorldID world, dSpaceID space, const FieldConfig& field, const WorldConfig& cfg,
               double dt);
  // Contacts.cpp: the friction drift correction of one sole point on the
  // ground (reads sole_anchors, writes the point's anchor into `anchors`).
  void anchorSolePoint(const ContactCandidate& c, const WorldConfig& cfg, double dt,
                       std::map<std::array<int, 3>, Eigen::Vector2d>& anchors, dContact& contact) const;
  // Contacts.cpp: after the step, appends the robot-link contact forces,
  // scaled by `scale` (1/substeps), to `out`.
  void gatherContacts(double scale, std::vector<LinkContact>& out) const;
};

// Field-frame pose of a robot torso at (x, y) m, heading theta rad, z m.
Eigen::Isometry3d planarPose(double x, double y, double theta, double z);

}  // namespace simswift
