// RobotBody: one robot as ODE bodies, hinges and geoms (see RobotBody.hpp).
//
// Construction order matters to ODE: hinges are created with every link in
// the zero posture, so ODE's hinge angle (measured from the pose at creation)
// equals the NAO joint angle and the hinge stops are the URDF limits. The
// requested posture is then applied by moving the bodies kinematically, which
// ODE's joints accept because they store their anchors in body coordinates.
#include "sim/nao_model/RobotBody.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/nao_model/Motors.hpp"

namespace simswift {

namespace {


void toOde(const Eigen::Matrix3d& r, dMatrix3 out) {
  // dMatrix3 is 3x4 row-major (the 4th column is padding).
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[i * 4 + j] = r(i, j);
    out[i * 4 + 3] = 0;
  }
}

Eigen::Matrix3d fromOde(const dReal* r) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i * 4 + j];
  return m;
}

Eigen::Vector3d vec(const dReal* v) { return Eigen::Vector3d(v[0], v[1], v[2]); }

std::vector<ServoBank::Limits> servoLimits(const RobotModel& model) {
  std::vector<ServoBank::Limits> out;
  for (const auto& j : model.joints()) {
    ServoBank::Limits l{j.lower, j.upper, j.max_velocity, j.max_effort};
    // Speed and stall torque come from the URDF (which agrees with the motor
    // table, tests/nao_model); the electrical side from the motor table.
    if (const auto m = naoJointMotor(j.name)) {
      l.reduction = m->reduction;
      l.torque_constant = m->motor.torqueConstant();
      l.resistance = m->motor.resistance();
    }
    out.push_back(l);
  }
  return out;
}

// Inertia tensor (kg*m^2, link axes) with every principal moment raised to at
// least `floor`: the motors' reflected rotor inertia, and ODE conditioning.
Eigen::Matrix3d conditionedInertia(const Eigen::Matrix3d& inertia, double floor) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  Eigen::Vector3d moments = eig.eigenvalues().cwiseMax(floor);
  return eig.eigenvectors() * moments.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

RobotBody::RobotBody(const RobotModel& model, int robot_index, dWorldID world, dSpaceID space,
                     const Eigen::Isometry3d& torso_pose, const std::vector<double>& posture,
                     const ServoConfig& servo_config)
    : model_(&model), index_(robot_index), world_(world),
      servo_(servoLimits(model), servo_config) {
  const auto& links = model.links();
  const auto& joints = model.joints();
  const std::vector<Eigen::Isometry3d> zero =
      forwardKinematics(torso_pose, std::vector<double>(joints.size(), 0.0));

  // Bodies: origin at the CoM, axes parallel to the link frame.
  bodies_.resize(links.size());
  com_.resize(links.size());
  for (size_t l = 0; l < links.size(); ++l) {
    const LinkSpec& spec = links[l];
    com_[l] = spec.inertial_origin.xyz;
    const Eigen::Matrix3d r_io = spec.inertial_origin.rotation.toRotationMatrix();
    const Eigen::Matrix3d inertia = conditionedInertia(
        r_io * spec.inertia * r_io.transpose(), servo_config.min_link_inertia);
    dMass mass;
    dMassSetParameters(&mass, spec.mass, 0, 0, 0, inertia(0, 0), inertia(1, 1), inertia(2, 2),
                       inertia(0, 1), inertia(0, 2), inertia(1, 2));
    dBodyID b = dBodyCreate(world);
    dBodySetMass(b, &mass);
    bodies_[l] = b;
  }
  placeLinks(zero);

  // Hinges: body1 = child, body2 = parent, so a positive angle is the child
  // turning positively about the axis relative to its parent (NAO sign).
  joints_.resize(joints.size());
  motor_cap_.assign(joints.size(), 0.0);
  feedback_.resize(joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    const JointSpec& spec = joints[j];
    const Eigen::Isometry3d& frame = zero[spec.child_link];
    const Eigen::Vector3d anchor = frame.translation();
    const Eigen::Vector3d axis = frame.linear() * spec.axis;
    dJointID h = dJointCreateHinge(world, nullptr);
    dJointAttach(h, bodies_[spec.child_link], bodies_[spec.parent_link]);
    dJointSetHingeAnchor(h, anchor.x(), anchor.y(), anchor.z());
    dJointSetHingeAxis(h, axis.x(), axis.y(), axis.z());
    // The mechanical stops sit kStopBeyondLimit outside the range the servo
    // is commanded within, so a motor holding a joint at its limit holds it
    // there itself: a motor pressing against an ODE stop gets its whole FMax
    // applied for a step when it pulls away (the stop's "jumping"), and a
    // light link commanded to its limit (the kick's AnkleRoll, the hands at 0)
    // snapped 0.4 rad off the stop in one tick, every ~0.13 s.
    dJointSetHingeParam(h, dParamLoStop, spec.lower - kStopBeyondLimit);
    dJointSetHingeParam(h, dParamHiStop, spec.upper + kStopBeyondLimit);
    dJointSetHingeParam(h, dParamVel, 0);
    dJointSetHingeParam(h, dParamFMax, 0);
    dJointSetFeedback(h, &feedback_[j]);
    joints_[j] = h;
  }
  std::vector<JointProjector::Hinge> hinges;
  for (const JointSpec& spec : joints) {
    const Eigen::Vector3d anchor = zero[spec.child_link].translation();
    auto local = [&](int link) {
      return Eigen::Vector3d(linkPose(link).linear().transpose() * (anchor - vec(dBodyGetPosition(bodies_[link]))));
    };
    hinges.push_back({spec.child_link, spec.parent_link, local(spec.child_link), local(spec.parent_link)});
  }
  projector_ = std::make_unique<JointProjector>(bodies_, hinges);
  followers_.resize(joints.size());
  for (size_t j = 0; j < joints.size(); ++j)
    if (joints[j].mimic) followers_[model.jointIndex(*joints[j].mimic)].push_back(static_cast<int>(j));

  // Geoms: one per collision shape, in the given space, offset from the
  // body (CoM) frame. Self-collision is left to the world's callback, which
  // skips pairs whose tags name the same robot.
  for (size_t l = 0; l < links.size(); ++l) {
    for (const ShapeSpec& s : links[l].collisions) {
      dGeomID g = nullptr;
      switch (s.type) {
        case ShapeType::Box: g = dCreateBox(space, s.size.x(), s.size.y(), s.size.z()); break;
        case ShapeType::Sphere: g = dCreateSphere(space, s.radius); break;
        case ShapeType::Capsule: g = dCreateCapsule(space, s.radius, s.length); break;
        case ShapeType::Cylinder: g = dCreateCylinder(space, s.radius, s.length); break;
        case ShapeType::Mesh: continue;  // rejected by the loader
      }
      dGeomSetBody(g, bodies_[l]);
      const Eigen::Vector3d offset = s.origin.xyz - com_[l];
      dGeomSetOffsetPosition(g, offset.x(), offset.y(), offset.z());
      dMatrix3 r;
      toOde(s.origin.rotation.toRotationMatrix(), r);
      dGeomSetOffsetRotation(g, r);
      auto tag = std::make_unique<GeomTag>();
      tag->kind = GeomTag::RobotLink;
      tag->robot = robot_index;
      tag->link = static_cast<int32_t>(l);
      const int pj = links[l].parent_joint;
      const std::string& pjn = pj >= 0 ? joints[pj].name : std::string();
      tag->sole = s.type == ShapeType::Box && pjn.size() >= 9 &&
                  pjn.compare(pjn.size() - 9, 9, "AnkleRoll") == 0;
      dGeomSetData(g, tag.get());
      tags_.push_back(std::move(tag));
      geoms_.push_back(g);
    }
  }

  setPosture(posture);
}

RobotBody::~RobotBody() {
  for (dJointID j : joints_) dJointDestroy(j);
  for (dGeomID g : geoms_) dGeomDestroy(g);
  for (dBodyID b : bodies_) dBodyDestroy(b);
}

std::vector<Eigen::Isometry3d> RobotBody::forwardKinematics(
    const Eigen::Isometry3d& torso, const std::vector<double>& angles) const {
  const auto& joints = model_->joints();
  std::vector<Eigen::Isometry3d> pose(model_->links().size(), Eigen::Isometry3d::Identity());
  pose[model_->rootLink()] = torso;
  // Joints are ordered parent-before-child by the loader.
  for (size_t j = 0; j < joints.size(); ++j) {
    const JointSpec& spec = joints[j];
    const double q = j < angles.size() ? angles[j] : 0.0;
    pose[spec.child_link] = pose[spec.parent_link] * spec.origin.isometry() *
                            Eigen::AngleAxisd(q, spec.axis);
  }
  return pose;
}

void RobotBody::placeLinks(const std::vector<Eigen::Isometry3d>& poses) {
  for (size_t l = 0; l < bodies_.size(); ++l) {
    const Eigen::Vector3d p = poses[l] * com_[l];
    dMatrix3 r;
    toOde(poses[l].linear(), r);
    dBodySetPosition(bodies_[l], p.x(), p.y(), p.z());
    dBodySetRotation(bodies_[l], r);
    dBodySetLinearVel(bodies_[l], 0, 0, 0);
    dBodySetAngularVel(bodies_[l], 0, 0, 0);
    dBodySetForce(bodies_[l], 0, 0, 0);
    dBodySetTorque(bodies_[l], 0, 0, 0);
    dBodyEnable(bodies_[l]);
  }
}

void RobotBody::setPosture(const std::vector<double>& posture) {
  const auto& joints = model_->joints();
  std::vector<double> q(joints.size(), 0.0);
  for (size_t j = 0; j < joints.size(); ++j) {
    const double a = j < posture.size() && std::isfinite(posture[j]) ? posture[j] : 0.0;
    q[j] = std::clamp(a, joints[j].lower, joints[j].upper);
  }
  // Joints sharing a motor cannot disagree (the loader forbids chains).
  for (size_t j = 0; j < joints.size(); ++j) {
    if (!joints[j].mimic) continue;
    const int leader = model_->jointIndex(*joints[j].mimic);
    q[j] = std::clamp(q[leader] * joints[j].mimic_multiplier, joints[j].lower, joints[j].upper);
  }
  placeLinks(forwardKinematics(linkPose(model_->rootLink()), q));
  // The servos hold the new posture (stiffness unchanged).
  for (size_t j = 0; j < joints.size(); ++j)
    servo_.setTarget(static_cast<int>(j), q[j], servo_.stiffness(static_cast<int>(j)));
  for (auto& f : feedback_) f = dJointFeedback{};
}

void RobotBody::teleport(const Eigen::Isometry3d& torso_pose) {
  const Eigen::Isometry3d to_new = torso_pose * linkPose(model_->rootLink()).inverse();
  std::vector<Eigen::Isometry3d> poses(bodies_.size());
  for (size_t l = 0; l < bodies_.size(); ++l) poses[l] = to_new * linkPose(static_cast<int>(l));
  placeLinks(poses);
  for (auto& f : feedback_) f = dJointFeedback{};
}

void RobotBody::holdPosture(const std::vector<double>& posture, float stiffness) {
  const auto& joints = model_->joints();
  for (size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].mimic) continue;  // follows its leader
    const float angle = j < posture.size() ? static_cast<float>(posture[j]) : 0.0f;
    setTarget(static_cast<int>(j), angle, stiffness);
  }
}

void RobotBody::setTarget(int joint, double angle, double stiffness) {
  servo_.setTarget(joint, angle, stiffness);
  const auto& joints = model_->joints();
  for (int f : followers_[joint]) servo_.follow(f, joint, joints[f].mimic_multiplier);
}

void RobotBody::applyServos(double dt) {
  for (size_t j = 0; j < joints_.size(); ++j) {
    const int k = static_cast<int>(j);
    // Current and heat from the torque the motor delivered last substep: the
    // hinge's torque, less what the joint stop took beyond the motor's cap.
    const double cap = motor_cap_[j];
    servo_.heat(k, std::clamp(jointTorque(k), -cap, cap), dt);
    const ServoBank::Drive d = servo_.drive(k, jointAngle(k), dt);
    motor_cap_[j] = d.max_torque;
    dJointSetHingeParam(joints_[j], dParamVel, d.velocity);
    dJointSetHingeParam(joints_[j], dParamFMax, d.max_torque);
    // ODE's motor row with CFM c satisfies w = velocity - c * torque: the
    // DC motor's torque-speed line, solved implicitly (Servo.hpp).
    dJointSetHingeParam(joints_[j], dParamCFM, d.compliance);
  }
}

double RobotBody::anchorSeparation() const {
  double worst = 0;
  for (dJointID h : joints_) {
    dVector3 a1, a2;
    dJointGetHingeAnchor(h, a1);   // as attached to the child
    dJointGetHingeAnchor2(h, a2);  // as attached to the parent
    worst = std::max(worst, (vec(a1) - vec(a2)).norm());
  }
  return worst;
}

double RobotBody::jointAngle(int joint) const { return dJointGetHingeAngle(joints_[joint]); }

double RobotBody::jointVelocity(int joint) const { return dJointGetHingeAngleRate(joints_[joint]); }

double RobotBody::jointTorque(int joint) const {
  // Motor + stop torque on the child about the hinge axis: the child's
  // constraint wrench (force f1 at its CoM, torque t1) taken about the
  // anchor, where the positional rows act, projected on the axis.
  const JointSpec& spec = model_->joints()[joint];
  const dJointFeedback& fb = feedback_[joint];
  dVector3 a, ax;
  dJointGetHingeAnchor(joints_[joint], a);
  dJointGetHingeAxis(joints_[joint], ax);
  const Eigen::Vector3d com = vec(dBodyGetPosition(bodies_[spec.child_link]));
  const Eigen::Vector3d moment = vec(fb.t1) + (com - vec(a)).cross(vec(fb.f1));
  return moment.dot(vec(ax));
}

Eigen::Isometry3d RobotBody::linkPose(int link) const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = fromOde(dBodyGetRotation(bodies_[link]));
  t.translation() = vec(dBodyGetPosition(bodies_[link])) - t.linear() * com_[link];
  return t;
}

RobotBody::TorsoPose RobotBody::torsoPose() const {
  const Eigen::Isometry3d torso = linkPose(model_->rootLink());
  const Eigen::Vector3d fwd = torso.linear().col(0);
  return {torso.translation().x(), torso.translation().y(), torso.translation().z(), std::atan2(fwd.y(), fwd.x())};
}

Eigen::Vector3d RobotBody::linkLinearVelocity(int link, const Eigen::Vector3d& point_in_link) const {
  const Eigen::Vector3d p = linkPose(link) * point_in_link;
  dVector3 v;
  dBodyGetPointVel(bodies_[link], p.x(), p.y(), p.z(), v);
  return vec(v);
}

Eigen::Vector3d RobotBody::linkAngularVelocity(int link) const {
  return vec(dBodyGetAngularVel(bodies_[link]));
}

double RobotBody::lowestPoint() const {
  double lowest = std::numeric_limits<double>::infinity();
  for (dGeomID g : geoms_) {
    dReal aabb[6];
    dGeomGetAABB(g, aabb);
    lowest = std::min<double>(lowest, aabb[4]);
  }
  return lowest;
}

bool RobotBody::blownUp(double max_linear, double max_angular) const {
  for (dBodyID b : bodies_) {
    const Eigen::Vector3d p = vec(dBodyGetPosition(b));
    const Eigen::Vector3d v = vec(dBodyGetLinearVel(b));
    const Eigen::Vector3d w = vec(dBodyGetAngularVel(b));
    const dReal* q = dBodyGetQuaternion(b);
    if (!p.allFinite() || !v.allFinite() || !w.allFinite()) return true;
    if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]) || !std::isfinite(q[3]))
      return true;
    if (v.norm() > max_linear || w.norm() > max_angular) return true;
  }
  return false;
}

}  // namespace simswift
