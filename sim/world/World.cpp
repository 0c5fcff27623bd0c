// The ODE world: construction, placement, the fixed tick and blow-up
// recovery. Contacts are in Contacts.cpp, the field geoms in
// FieldGeometry.cpp, the hash in StateHash.cpp.
//
// The settings WorldConfig defaults to (QuickStep, 20 iterations,
// over-relaxation 1.7, ERP 0.8, steps of at most 5 ms, the inertia floor,
// sole anchors, joint projection) are what stood and kept speed when
// measured: the tables, with how and when each was measured, are
// docs/world.md, "Measurements".

// ORDER OF ONE TICK (step()), fixed; each substep of dt = tick / substeps:
//   1. checkBlowUps      a robot or the ball with NaN/inf, absurd speed or far
//                        away is reset (+ WorldEvent) BEFORE it is integrated:
//                        ODE aborts (dxNormalize3/4) rather than returning
//   2. applyPushes       first substep only: pending pushes become forces on
//                        the torsos (F = J / dt gives exactly the impulse J)
//   3. applyServos       every robot's servos set their hinge motors
//   4. collide           contacts sorted, contact joints created (sole
//                        points' friction anchored)
//   5. integrate         ODE's random generator (QuickStep's row shuffle)
//                        reseeded from the tick, then dWorldStep/QuickStep(dt)
//   6. gatherContacts    contact forces on robot links, scaled 1/substeps
//   7. projectJoints     each robot's hinge anchors brought back together
//   8. clearContacts     contact joints removed
// then checkBlowUps once more and the tick counter + 1.
#include <cmath>
#include <mutex>
#include <sstream>

#include "sim/world/ConfigError.hpp"
#include "sim/world/WorldImpl.hpp"

namespace simswift {

namespace {

void initOdeOnce() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
}

// Placement height (m) for the torso before re-seating on the ground: high
// enough that no posture reaches below the carpet.
constexpr double kPlacementZ = 1.0;

}  // namespace

Eigen::Isometry3d planarPose(double x, double y, double theta, double z) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, z);
  p.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

std::optional<WorldConfigProblem> checkWorldConfig(const WorldConfig& c) {
  std::optional<WorldConfigProblem> bad;
  auto rule = [&](const char* field, double v, const Range& r) {
    if (bad || r.contains(v)) return;
    std::ostringstream got;
    got << v;
    bad = WorldConfigProblem{field, r.describe() + " (got " + got.str() + ")"};
  };
  const Range unit = Range::closed(0, 1);
  rule("substeps", c.substeps, Range::closed(0, 100));  // 0: the fewest steps of at most max_substep_us
  rule("max_substep_us", static_cast<double>(c.max_substep_us), Range::closed(100, 100000));  // us
  rule("tick_us", static_cast<double>(c.tick_us), Range::closed(1000, 100000));  // us
  rule("quick_iterations", c.quick_iterations, Range::closed(1, 1000));
  rule("quick_w", c.quick_w, Range{0.0, 2.0, true, true});  // QuickStep's over-relaxation converges in (0, 2)
  rule("erp", c.erp, unit);
  rule("cfm", c.cfm, unit);
  rule("joint_projection_sweeps", c.joint_projection_sweeps, Range::closed(0, 1000));
  rule("joint_projection_tolerance", c.joint_projection_tolerance, Range::positive());  // m
  const int most = WorldConfig::kMaxSolePoints;
  rule("sole_nx", c.sole_nx, Range::closed(1, most));
  rule("sole_ny", c.sole_ny, Range::closed(1, most));
  if (!bad && c.sole_nx * c.sole_ny > most)
    bad = WorldConfigProblem{"sole_ny", "sole_nx x sole_ny must be at most " + std::to_string(most) + " points (got " +
                                            std::to_string(c.sole_nx) + " x " + std::to_string(c.sole_ny) + ")"};
  rule("sole_stiffness", c.sole_stiffness, Range::positive());  // N/m
  rule("sole_damping", c.sole_damping, Range::nonNegative());  // N*s/m
  rule("sole_anchor_erp", c.sole_anchor_erp, unit);
  rule("sole_anchor_slip", c.sole_anchor_slip, Range::positive());  // m
  return bad;
}

World::World(const FieldConfig& field, const WorldConfig& config)
    : impl_(std::make_unique<Impl>()), field_(field), config_(config) {
  if (auto bad = checkWorldConfig(config_)) throw ConfigError("world: " + bad->field + ": " + bad->why);
  initOdeOnce();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, -config_.gravity);
  dWorldSetERP(world_, config_.erp);
  dWorldSetCFM(world_, config_.cfm);
  dWorldSetQuickStepNumIterations(world_, config_.quick_iterations);
  dWorldSetQuickStepW(world_, config_.quick_w);
  // Let resting contacts sink 1 mm before pushing back (stops jitter), and
  // cap the push-out speed so deep penetrations resolve without a kick.
  dWorldSetContactSurfaceLayer(world_, 0.001);
  dWorldSetContactMaxCorrectingVel(world_, 1.0);
  dWorldSetAutoDisableFlag(world_, 0);

  space_ = dSimpleSpaceCreate(nullptr);
  impl_->static_space = dSimpleSpaceCreate(space_);
  impl_->contact_group = dJointGroupCreate(0);
  impl_->buildField(field_);

  // The ball: a solid sphere (I = 2/5 m r^2). The SPL ball is a thick
  // plastic shell; the rolling resistance in the field YAML is tuned for
  // this inertia.
  const double r = field_.ball.diameter / 2;
  impl_->ball = dBodyCreate(world_);
  dMass m;
  dMassSetSphereTotal(&m, field_.ball.mass, r);
  dBodySetMass(impl_->ball, &m);
  // ODE's damping is a per-step fraction of velocity removed: rate (1/s) * dt.
  dBodySetLinearDamping(impl_->ball, field_.ball.linear_damping * tickSeconds() / substeps());
  impl_->ball_geom = dCreateSphere(space_, r);
  dGeomSetBody(impl_->ball_geom, impl_->ball);
  dGeomSetData(impl_->ball_geom, &impl_->ball_tag);
  placeBall(0, 0);

  impl_->ray = dCreateRay(nullptr, 1.0);
}

World::~World() {
  robots_.clear();  // RobotBody removes its own bodies, joints and geoms
  if (impl_->ray) dGeomDestroy(impl_->ray);
  dJointGroupDestroy(impl_->contact_group);
  dSpaceDestroy(space_);  // cleanup mode: destroys the sub-spaces and their geoms
  dWorldDestroy(world_);
}

int World::addRobot(std::shared_ptr<const RobotModel> model, double x, double y, double theta,
                    const std::vector<double>& posture) {
  const int index = numRobots();
  dSpaceID rs = dSimpleSpaceCreate(space_);
  impl_->robot_spaces.push_back(rs);
  impl_->models.push_back(model);
  impl_->placements.push_back({});
  impl_->pending_impulse.push_back(Eigen::Vector3d::Zero());
  robots_.push_back(std::make_unique<RobotBody>(*model, index, world_, rs,
                                                planarPose(x, y, theta, kPlacementZ), posture,
                                                config_.servo));
  placeRobot(index, x, y, theta, posture);
  return index;
}

void World::checkPlacement(const char* what, double x, double y, double theta) const {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(theta) || std::fabs(x) > config_.max_distance ||
      std::fabs(y) > config_.max_distance || std::fabs(theta) > 100)
    throw WorldError(std::string(what) + ": position (" + std::to_string(x) + ", " + std::to_string(y) +
                     ") m, heading " + std::to_string(theta) + " rad is not finite or beyond " +
                     std::to_string(config_.max_distance) + " m");
}

void World::placeRobot(int i, double x, double y, double theta,
                       const std::vector<double>& posture) {
  checkPlacement("placeRobot", x, y, theta);
  RobotBody& rb = *robots_.at(i);
  rb.teleport(planarPose(x, y, theta, kPlacementZ));
  rb.setPosture(posture);
  // Re-seat: lower the whole robot so its lowest collision point is at z = 0.
  const double drop = rb.lowestPoint();
  rb.teleport(planarPose(x, y, theta, kPlacementZ - drop));
  impl_->placements[i] = {x, y, theta, posture};
  // Its soles touch down afresh where they now are.
  for (auto it = impl_->sole_anchors.begin(); it != impl_->sole_anchors.end();)
    it = it->first[0] == i ? impl_->sole_anchors.erase(it) : std::next(it);
}

void World::placeBall(double x, double y) {
  if (!hasBall()) throw WorldError("placeBall: the ball was removed (ball: none)");
  checkPlacement("placeBall", x, y, 0);
  const double r = field_.ball.diameter / 2;
  impl_->ball_placed = Eigen::Vector3d(x, y, r);
  dBodySetPosition(impl_->ball, x, y, r);
  const dQuaternion identity = {1, 0, 0, 0};
  dBodySetQuaternion(impl_->ball, identity);
  dBodySetLinearVel(impl_->ball, 0, 0, 0);
  dBodySetAngularVel(impl_->ball, 0, 0, 0);
}

void World::setBallVelocity(const Eigen::Vector3d& v) {
  if (!v.allFinite() || v.norm() > config_.blowup_linear_speed)
    throw WorldError("setBallVelocity: " + std::to_string(v.norm()) + " m/s is not finite or beyond " +
                     std::to_string(config_.blowup_linear_speed) + " m/s");
  dBodySetLinearVel(impl_->ball, v.x(), v.y(), v.z());
}

Eigen::Vector3d World::ballPosition() const {
  const dReal* p = dBodyGetPosition(impl_->ball);
  return {p[0], p[1], p[2]};
}

Eigen::Quaterniond World::ballOrientation() const {
  const dReal* q = dBodyGetQuaternion(impl_->ball);  // ODE order: w, x, y, z
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

dBodyID World::ballBody() const { return impl_->ball; }

void World::removeBall() {
  if (!hasBall()) return;
  dBodySetLinearVel(impl_->ball, 0, 0, 0);
  dBodySetAngularVel(impl_->ball, 0, 0, 0);
  dBodyDisable(impl_->ball);
  dGeomDisable(impl_->ball_geom);
  impl_->ball_removed = true;
}

bool World::hasBall() const { return !impl_->ball_removed; }

Eigen::Vector3d World::ballVelocity() const {
  const dReal* v = dBodyGetLinearVel(impl_->ball);
  return {v[0], v[1], v[2]};
}

void World::applyImpulse(int robot, const Eigen::Vector3d& impulse) {
  if (robot < 0 || robot >= numRobots()) throw WorldError("applyImpulse: no robot " + std::to_string(robot));
  if (!impulse.allFinite() || impulse.norm() > kMaxPushImpulse)
    throw WorldError("applyImpulse: " + std::to_string(impulse.norm()) + " N*s is not finite or beyond " +
                     std::to_string(kMaxPushImpulse) + " N*s");
  impl_->pending_impulse[robot] += impulse;
}

void World::step() {
  stepPhysics(tick_);
  ++tick_;
  checkBlowUps();
}

void World::settle(int ticks) {
  // Seeds below every counted tick's (integrate: tick * 16 + substep), so
  // no settling substep shares a seed with a tick of the run.
  for (int k = 0; k < ticks; ++k) {
    stepPhysics(-1 - k);
    checkBlowUps();
  }
}

void World::stepPhysics(int64_t seed_tick) {
  const int n = substeps();
  const double dt = tickSeconds() / n;
  contacts_.clear();
  for (int sub = 0; sub < n; ++sub) {
    checkBlowUps();
    if (sub == 0) applyPendingPushes(dt);
    for (auto& r : robots_) r->applyServos(dt);
    impl_->collide(world_, space_, field_, config_, dt);
    integrate(seed_tick, sub, dt);
    impl_->gatherContacts(1.0 / n, contacts_);
    if (config_.joint_projection_sweeps > 0) projectJoints();
    dJointGroupEmpty(impl_->contact_group);
  }
}

void World::applyPendingPushes(double dt) {
  for (int i = 0; i < numRobots(); ++i) {
    Eigen::Vector3d& j = impl_->pending_impulse[i];
    if (j.isZero()) continue;
    const Eigen::Vector3d f = j / dt;  // N over one substep: exactly the impulse
    dBodyAddForce(robots_[i]->torsoBody(), f.x(), f.y(), f.z());
    j.setZero();
  }
}

void World::integrate(int64_t seed_tick, int substep, double dt) {
  // QuickStep shuffles its constraint rows with ODE's one process-wide
  // random generator; reseeding it from the tick makes every world's
  // result a function of its own state, whatever other worlds did. Worlds
  // stepping on other threads draw from the same generator: the seed and
  // the step it feeds are one critical section, so a world's result does
  // not depend on how many run beside it (tests/world/test_physics_hash.cpp).
  static std::mutex ode_random;
  std::lock_guard<std::mutex> lock(ode_random);
  dRandSetSeed(static_cast<unsigned long>(seed_tick) * 16u + static_cast<unsigned long>(substep));
  if (config_.solver == WorldConfig::Solver::Exact) {
    dWorldStep(world_, dt);
  } else {
    dWorldQuickStep(world_, dt);
  }
}

// Each robot's hinge anchors brought back together. Feet standing on their
// soles (a sole point on the ground this substep) are held by their
// anchored friction and stay; any other link may move by the fraction of a
// millimetre the pass needs (a contact it presses into pushes back).
void World::projectJoints() {
  for (int i = 0; i < numRobots(); ++i) {
    std::vector<char>& pinned = impl_->pinned;
    pinned.assign(impl_->models[i]->links().size(), 0);
    for (const Impl::Feedback& m : impl_->feedback_meta)
      if (m.robot == i && m.sole) pinned[m.link] = 1;
    robots_[i]->projectJoints(pinned, config_.joint_projection_sweeps, config_.joint_projection_tolerance);
  }
}

// Blow-ups: a robot or the ball with NaN/inf, absurd speed or far away is put
// back where it was last placed; the run goes on and the event is reported.
void World::checkBlowUps() {
  auto far = [&](const Eigen::Vector3d& p) { return (p.array().abs() > config_.max_distance).any(); };
  for (int i = 0; i < numRobots(); ++i) {
    const bool bad = robots_[i]->blownUp(config_.blowup_linear_speed, config_.blowup_angular_speed) ||
                     far(Eigen::Vector3d(dBodyGetPosition(robots_[i]->torsoBody())));
    if (!bad) continue;
    impl_->pending_impulse[i].setZero();
    const Impl::Placement p = impl_->placements[i];
    placeRobot(i, p.x, p.y, p.theta, p.posture);
    events_.push_back({WorldEvent::Kind::BlowUp, tick_, i,
                       "robot " + std::to_string(i) +
                           " blew up (NaN or speed beyond limits); reset to its last placement"});
  }
  if (!hasBall()) return;
  const Eigen::Vector3d bp = ballPosition(), bv = ballVelocity();
  const dReal* bw = dBodyGetAngularVel(impl_->ball);
  const bool ball_bad = !bp.allFinite() || !bv.allFinite() || !std::isfinite(bw[0]) ||
                        !std::isfinite(bw[1]) || !std::isfinite(bw[2]) ||
                        bv.norm() > config_.blowup_linear_speed ||
                        Eigen::Vector3d(bw[0], bw[1], bw[2]).norm() > config_.blowup_angular_speed || far(bp);
  if (ball_bad) {
    placeBall(impl_->ball_placed.x(), impl_->ball_placed.y());
    events_.push_back({WorldEvent::Kind::BlowUp, tick_, -1,
                       "ball blew up (NaN or speed beyond limits); reset to its last placement"});
  }
}

std::vector<WorldEvent> World::takeEvents() {
  std::vector<WorldEvent> out;
  out.swap(events_);
  return out;
}

namespace {

struct RayQuery {
  dSpaceID ignore_space;  // the ignored robot's space, or null
  int ignore_robot;
  double best;
};

void rayCallback(void* data, dGeomID o1, dGeomID o2) {
  auto* q = static_cast<RayQuery*>(data);
  if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
    dGeomID sp = dGeomIsSpace(o1) ? o1 : o2;
    if (reinterpret_cast<dSpaceID>(sp) == q->ignore_space) return;
    dSpaceCollide2(o1, o2, data, &rayCallback);
    return;
  }
  for (dGeomID g : {o1, o2}) {
    if (dGeomGetClass(g) == dRayClass) continue;
    const auto* tag = static_cast<const GeomTag*>(dGeomGetData(g));
    if (tag && tag->kind == GeomTag::RobotLink && tag->robot == q->ignore_robot) return;
  }
  dContactGeom c;
  if (dCollide(o1, o2, 1, &c, sizeof(c)) > 0 && c.depth < q->best) q->best = c.depth;
}

}  // namespace

double World::rayCast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_range,
                      int ignore_robot) const {
  const Eigen::Vector3d d = dir.normalized();
  dGeomRaySetLength(impl_->ray, max_range);
  dGeomRaySet(impl_->ray, origin.x(), origin.y(), origin.z(), d.x(), d.y(), d.z());
  RayQuery q{nullptr, ignore_robot, max_range + 1};
  if (ignore_robot >= 0 && ignore_robot < numRobots()) {
    q.ignore_space = impl_->robot_spaces[ignore_robot];
  }
  dSpaceCollide2(impl_->ray, reinterpret_cast<dGeomID>(space_), &q, &rayCallback);
  return q.best <= max_range ? q.best : -1.0;
}

}  // namespace simswift
