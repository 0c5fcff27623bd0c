// Collision detection and contact joints for one physics substep.
//
// Spaces: the world space holds the static-field space, the ball geom and
// one space per robot. Space pairs are expanded with dSpaceCollide2, and a
// space is never collided with itself, so a robot's own links and the static
// geoms never meet each other.
//
// Determinism: the candidate contacts are sorted by (tag kinds, robots,
// links, position) before any joint is created, so the joint order (which
// the solver's result depends on) is a function of the state only.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "sim/world/WorldImpl.hpp"

namespace simswift {

namespace {

constexpr int kMaxContactsPerPair = 8;
constexpr double kBounceVelocity = 0.05;  // m/s: slower impacts do not bounce

const GeomTag kUntagged{GeomTag::Ground, -1, -1};

const GeomTag& tagOf(dGeomID g) {
  const void* d = dGeomGetData(g);
  return d ? *static_cast<const GeomTag*>(d) : kUntagged;
}

struct CollideData {
  std::vector<ContactCandidate>* out;
  const WorldConfig* cfg;
};

// A sole box on the ground plane z = 0: one contact per grid point of the
// box's bottom face that is below the plane (depth = how far below). The
// box's own collider returns at most its 4 corners, so a sole tilted by a
// fraction of a degree stands on an edge; the grid spreads the load over
// the whole sole (the FSRs read it) and, with the springs' give, keeps the
// stance foot flat.
// `index` receives each contact's grid index (i * sole_ny + j).
int soleContacts(dGeomID sole, dGeomID plane, const WorldConfig& cfg, dContactGeom* out, int* index, int max) {
  dVector3 half;
  dGeomBoxGetLengths(sole, half);
  for (double& h : half) h *= 0.5;
  const dReal* p = dGeomGetPosition(sole);
  const dReal* r = dGeomGetRotation(sole);  // 3x4 row-major
  // Which face is the bottom: the box axis most nearly vertical.
  int up = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(r[8 + k]) > std::fabs(r[8 + up])) up = k;
  const double sign = r[8 + up] > 0 ? -1.0 : 1.0;  // toward the ground
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  int n = 0;
  for (int i = 0; i < cfg.sole_nx; ++i) {
    for (int j = 0; j < cfg.sole_ny; ++j) {
      if (n >= max) return n;
      double local[3];
      local[up] = sign * half[up];
      local[a] = half[a] * (cfg.sole_nx > 1 ? -1.0 + 2.0 * i / (cfg.sole_nx - 1) : 0.0);
      local[b] = half[b] * (cfg.sole_ny > 1 ? -1.0 + 2.0 * j / (cfg.sole_ny - 1) : 0.0);
      double w[3];
      for (int k = 0; k < 3; ++k) w[k] = p[k] + r[4 * k] * local[0] + r[4 * k + 1] * local[1] + r[4 * k + 2] * local[2];
      if (w[2] >= 0) continue;
      index[n] = i * cfg.sole_ny + j;
      dContactGeom& c = out[n++];
      c.pos[0] = w[0];
      c.pos[1] = w[1];
      c.pos[2] = w[2];
      c.pos[3] = 0;
      c.normal[0] = c.normal[1] = 0;
      c.normal[2] = 1;  // moving the sole (g1) up separates
      c.normal[3] = 0;
      c.depth = -w[2];
      c.g1 = sole;
      c.g2 = plane;
      c.side1 = c.side2 = -1;
    }
  }
  return n;
}

void nearCallback(void* raw, dGeomID o1, dGeomID o2) {
  auto* data = static_cast<CollideData*>(raw);
  auto* out = data->out;
  if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
    dSpaceCollide2(o1, o2, raw, &nearCallback);
    return;
  }
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  if (!b1 && !b2) return;  // static-static
  const GeomTag& t1 = tagOf(o1);
  const GeomTag& t2 = tagOf(o2);
  if (t1.kind == GeomTag::RobotLink && t2.kind == GeomTag::RobotLink && t1.robot == t2.robot) {
    return;  // own links (cannot happen with one space per robot; kept as a guard)
  }
  // Sole on the carpet: the contact patch (the ground is the plane z = 0).
  const bool sole_ground = (t1.sole && t2.kind == GeomTag::Ground && dGeomGetClass(o2) == dPlaneClass) ||
                           (t2.sole && t1.kind == GeomTag::Ground && dGeomGetClass(o1) == dPlaneClass);
  if (sole_ground && dGeomGetClass(t1.sole ? o1 : o2) == dBoxClass) {
    dContactGeom cg[WorldConfig::kMaxSolePoints];
    int index[WorldConfig::kMaxSolePoints];
    const int n = t1.sole ? soleContacts(o1, o2, *data->cfg, cg, index, WorldConfig::kMaxSolePoints)
                          : soleContacts(o2, o1, *data->cfg, cg, index, WorldConfig::kMaxSolePoints);
    for (int i = 0; i < n; ++i)
      out->push_back(t1.sole ? ContactCandidate{cg[i], t1, t2, index[i]} : ContactCandidate{cg[i], t2, t1, index[i]});
    return;
  }
  dContactGeom cg[kMaxContactsPerPair];
  int n = dCollide(o1, o2, kMaxContactsPerPair, cg, sizeof(dContactGeom));
  for (int i = 0; i < n; ++i) out->push_back({cg[i], t1, t2});
}

// Sort key: independent of pointer values and of the order ODE visited pairs.
auto sortKey(const ContactCandidate& c) {
  const GeomTag& lo = (c.a.kind < c.b.kind || (c.a.kind == c.b.kind && c.a.robot <= c.b.robot))
                          ? c.a : c.b;
  const GeomTag& hi = (&lo == &c.a) ? c.b : c.a;
  return std::make_tuple(static_cast<int>(lo.kind), static_cast<int>(hi.kind), lo.robot, lo.link,
                         hi.robot, hi.link, c.geom.pos[0], c.geom.pos[1], c.geom.pos[2],
                         c.geom.depth);
}

// ERP/CFM giving a damped spring of stiffness k (N/m) and damping c (N*s/m)
// over a step dt (the ODE manual's relation).
void springSurface(dSurfaceParameters& s, double k, double c, double dt) {
  s.mode |= dContactSoftERP | dContactSoftCFM;
  s.soft_erp = dt * k / (dt * k + c);
  s.soft_cfm = 1.0 / (dt * k + c);
}

dSurfaceParameters surfaceFor(const GeomTag& a, const GeomTag& b, const FieldConfig& field,
                              const WorldConfig& cfg, double dt) {
  const SurfaceConfig& sc = field.surface;
  const BallConfig& ball = field.ball;
  dSurfaceParameters s{};
  s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM | dContactBounce;
  s.soft_erp = sc.soft_erp;
  s.soft_cfm = sc.soft_cfm;
  s.mu = sc.other_friction;
  s.bounce = 0;
  s.bounce_vel = kBounceVelocity;

  const bool ball_involved = a.kind == GeomTag::Ball || b.kind == GeomTag::Ball;
  const GeomTag::Kind other = a.kind == GeomTag::Ball ? b.kind : a.kind;
  if (ball_involved) {
    const double radius = ball.diameter / 2;
    switch (other) {
      case GeomTag::Ground:
        s.mu = sc.ball_friction;
        s.bounce = ball.ground_restitution;
        // Rolling resistance as ODE rolling friction: with Approx1 the
        // resisting torque is bounded by rho * normal force, so rho (m) =
        // coefficient * radius gives a resisting force of coefficient * N.
        s.mode |= dContactRolling;
        s.rho = s.rho2 = ball.rolling_friction * radius;
        s.rhoN = ball.rolling_friction * radius;  // also kills spin about the normal
        break;
      case GeomTag::Net:
        // The net gives and absorbs: a soft, heavily damped contact, grippy.
        s.mu = 1.0;
        s.bounce = 0;
        s.mode &= ~dContactBounce;
        s.mode |= dContactRolling;
        s.rho = s.rho2 = s.rhoN = ball.rolling_friction * radius;
        springSurface(s, field.goal.net_stiffness, field.goal.net_damping, dt);
        break;
      default:  // posts, crossbar, robots
        s.bounce = ball.restitution;
        break;
    }
    return s;
  }
  const bool ground = a.kind == GeomTag::Ground || b.kind == GeomTag::Ground;
  if (ground) s.mu = sc.friction;  // feet (or any link) on the carpet
  if (ground && (a.sole || b.sole)) {
    // One point of the sole grid: its share of the sole's spring and damper.
    const double n = static_cast<double>(std::max(1, cfg.sole_nx * cfg.sole_ny));
    springSurface(s, cfg.sole_stiffness / n, cfg.sole_damping / n, dt);
  }
  return s;
}

}  // namespace

void World::Impl::collide(dWorldID world, dSpaceID space, const FieldConfig& field,
                          const WorldConfig& cfg, double dt) {
  candidates.clear();
  CollideData data{&candidates, &cfg};
  dSpaceCollide(space, &data, &nearCallback);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const ContactCandidate& x, const ContactCandidate& y) { return sortKey(x) < sortKey(y); });

  feedback.clear();
  feedback_meta.clear();
  // Reserve first: dJointSetFeedback keeps raw pointers into this vector.
  size_t robot_contacts = 0;
  for (const ContactCandidate& c : candidates) {
    robot_contacts += (c.a.kind == GeomTag::RobotLink) + (c.b.kind == GeomTag::RobotLink);
  }
  feedback.reserve(robot_contacts);

  std::map<std::array<int, 3>, Eigen::Vector2d> anchors;
  for (const ContactCandidate& c : candidates) {
    dContact contact{};
    contact.geom = c.geom;
    contact.surface = surfaceFor(c.a, c.b, field, cfg, dt);
    if (c.sole_point >= 0 && cfg.sole_anchor_erp > 0) anchorSolePoint(c, cfg, dt, anchors, contact);
    dBodyID b1 = dGeomGetBody(c.geom.g1), b2 = dGeomGetBody(c.geom.g2);
    GeomTag first = c.a, second = c.b;
    if (!b1) {
      // Keep a real body first so feedback f1 belongs to it: swap the bodies
      // and flip the normal (which points into the first body).
      std::swap(b1, b2);
      std::swap(first, second);
      for (int k = 0; k < 3; ++k) contact.geom.normal[k] = -contact.geom.normal[k];
      std::swap(contact.geom.g1, contact.geom.g2);
    }
    dJointID j = dJointCreateContact(world, contact_group, &contact);
    dJointAttach(j, b1, b2);

    const bool r1 = first.kind == GeomTag::RobotLink, r2 = second.kind == GeomTag::RobotLink;
    if (r1 || r2) {
      feedback.push_back(dJointFeedback{});
      dJointSetFeedback(j, &feedback.back());
      const Eigen::Vector3d p(c.geom.pos[0], c.geom.pos[1], c.geom.pos[2]);
      if (r1) {
        feedback_meta.push_back({first.robot, first.link, second.kind, second.robot, true,
                                 feedback.size() - 1, p, c.sole_point >= 0});
      }
      if (r2) {
        feedback_meta.push_back({second.robot, second.link, first.kind, first.robot, false,
                                 feedback.size() - 1, p, c.sole_point >= 0});
      }
    }
  }
  sole_anchors.swap(anchors);
}

// Static friction that holds. ODE's friction rows are velocity constraints
// with no position term, and QuickStep leaves a small velocity residual every
// substep, so a loaded sole creeps (2.7 mm per step at 300 mm/s, measured)
// where a real foot on carpet sticks. Like ERP for a joint anchor, the
// friction rows of a sticking sole point are asked for the velocity that
// removes sole_anchor_erp of its drift from where it touched down, bounded by
// the friction cone as any friction force is: a foot pushed harder than
// mu * N still slides, and past sole_anchor_slip it re-anchors.
void World::Impl::anchorSolePoint(const ContactCandidate& c, const WorldConfig& cfg, double dt,
                                  std::map<std::array<int, 3>, Eigen::Vector2d>& anchors, dContact& contact) const {
  const std::array<int, 3> key{c.a.robot, c.a.link, c.sole_point};
  const Eigen::Vector2d here(c.geom.pos[0], c.geom.pos[1]);
  const auto old = sole_anchors.find(key);
  Eigen::Vector2d anchor = here;
  if (old != sole_anchors.end() && (old->second - here).norm() <= cfg.sole_anchor_slip) anchor = old->second;
  anchors[key] = anchor;
  const Eigen::Vector2d drift = anchor - here;  // m: where the point should be, from where it is
  const double d = drift.norm();
  if (d < 1e-9) return;
  // Friction direction 1 along the drift; the sole (body 1) is asked to move
  // back along it at erp * d / dt, direction 2 (across) to stay still.
  contact.surface.mode |= dContactFDir1 | dContactMotion1;
  contact.fdir1[0] = drift.x() / d;
  contact.fdir1[1] = drift.y() / d;
  contact.fdir1[2] = 0;
  contact.fdir1[3] = 0;
  contact.surface.motion1 = cfg.sole_anchor_erp * d / dt;
}

void World::Impl::gatherContacts(double scale, std::vector<LinkContact>& out) const {
  for (const Feedback& m : feedback_meta) {
    const dJointFeedback& fb = feedback[m.slot];
    const dReal* f = m.first ? fb.f1 : fb.f2;
    out.push_back({m.robot, m.link, m.other, m.other_robot, m.position,
                   Eigen::Vector3d(f[0], f[1], f[2]) * scale});
  }
}

}  // namespace simswift
