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

void nearCallback(void* data, dGeomID o1, dGeomID o2) {
  auto* out = static_cast<std::vector<ContactCandidate>*>(data);
  if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
    dSpaceCollide2(o1, o2, data, &nearCallback);
    return;
  }
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  if (!b1 && !b2) return;  // static-static
  const GeomTag& t1 = tagOf(o1);
  const GeomTag& t2 = tagOf(o2);
  if (t1.kind == GeomTag::RobotLink && t2.kind == GeomTag::RobotLink && t1.robot == t2.robot) {
    return;  // own links (cannot happen with one space per robot; kept as a guard)
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
                              double dt) {
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
  return s;
}

}  // namespace

void World::Impl::collide(dWorldID world, dSpaceID space, const FieldConfig& field,
                          const WorldConfig& cfg, double dt) {
  candidates.clear();
  dSpaceCollide(space, &candidates, &nearCallback);
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

  for (const ContactCandidate& c : candidates) {
    dContact contact{};
    contact.geom = c.geom;
    contact.surface = surfaceFor(c.a, c.b, field, dt);
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
                                 feedback.size() - 1, p});
      }
      if (r2) {
        feedback_meta.push_back({second.robot, second.link, first.kind, first.robot, false,
                                 feedback.size() - 1, p});
      }
    }
  }
  (void)cfg;
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
