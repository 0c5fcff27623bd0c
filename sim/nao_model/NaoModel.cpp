// NaoModel: loads the NAO's URDF with urdfdom and checks it is a robot the
// simulator can drive (every link has mass, every joint is a limited hinge,
// every libagent joint exists). Units as in NaoModel.hpp.
#include "sim/nao_model/NaoModel.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "agent/libagent/AgentShared.hpp"

namespace simswift {

Eigen::Isometry3d Pose3::isometry() const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation.normalized().toRotationMatrix();
  t.translation() = xyz;
  return t;
}

namespace {

namespace la = agent::libagent;

// urdfdom reports problems through console_bridge, not through its return
// value; this handler collects them so the ModelError can quote them.
class CaptureHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      if (!text_.empty()) text_ += "; ";
      text_ += text;
    }
  }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// console_bridge's handler is process-global.
std::mutex& parserMutex() {
  static std::mutex m;
  return m;
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw ModelError(source + ": " + what);
}

Pose3 toPose(const urdf::Pose& p) {
  Pose3 out;
  out.xyz = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  out.rotation = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  if (out.rotation.norm() < 1e-9) out.rotation = Eigen::Quaterniond::Identity();
  out.rotation.normalize();
  return out;
}

bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }

ShapeSpec toShape(const urdf::GeometrySharedPtr& g, const urdf::Pose& origin, bool collision,
                  const std::string& source, const std::string& link) {
  const std::string where = std::string(collision ? "collision" : "visual") + " of link '" + link + "'";
  if (!g) fail(source, where + " has no <geometry>");
  ShapeSpec s;
  s.origin = toPose(origin);
  switch (g->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*g);
      s.type = ShapeType::Box;
      s.size = Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z);
      if (!finite3(s.size) || (s.size.array() <= 0).any()) fail(source, where + ": box size must be positive");
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& sp = static_cast<const urdf::Sphere&>(*g);
      s.type = ShapeType::Sphere;
      s.radius = sp.radius;
      if (!(s.radius > 0)) fail(source, where + ": sphere radius must be positive");
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(*g);
      // Collision cylinders become capsules (length = straight part, caps of
      // the radius added at both ends): limbs then roll and slide smoothly
      // and ODE's capsule collisions are cheaper and more robust.
      s.type = collision ? ShapeType::Capsule : ShapeType::Cylinder;
      s.radius = c.radius;
      s.length = c.length;
      if (!(s.radius > 0) || !(s.length >= 0)) fail(source, where + ": cylinder radius/length invalid");
      break;
    }
    case urdf::Geometry::MESH: {
      if (collision) fail(source, where + ": mesh collision geometry is not supported (use box/sphere/cylinder)");
      const auto& m = static_cast<const urdf::Mesh&>(*g);
      s.type = ShapeType::Mesh;
      s.mesh = m.filename;
      s.size = Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z);
      break;
    }
    default:
      fail(source, where + ": unknown geometry type");
  }
  return s;
}

// Position of a joint in the NAO's 26-joint order (libagent order with
// RHipYawPitch just before RHipRoll); used to give links and joints a stable,
// familiar order instead of urdfdom's alphabetical maps.
double orderKey(const std::string& name) {
  for (int i = 0; i < la::kNumJoints; ++i)
    if (name == la::Joints::kNames[i]) return i;
  if (name == "RHipYawPitch") return la::Joints::RHipRoll - 0.5;
  return 1000.0;  // anything else after, alphabetically (ties keep name order)
}

}  // namespace

NaoModel NaoModel::loadUrdf(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ModelError(path + ": cannot open URDF file");
  std::stringstream ss;
  ss << in.rdbuf();
  return loadUrdfString(ss.str(), path);
}

NaoModel NaoModel::loadUrdfString(const std::string& xml, const std::string& source) {
  urdf::ModelInterfaceSharedPtr urdf;
  CaptureHandler capture;
  {
    std::lock_guard<std::mutex> lock(parserMutex());
    console_bridge::useOutputHandler(&capture);
    try {
      urdf = urdf::parseURDF(xml);
    } catch (const std::exception& e) {
      console_bridge::restorePreviousOutputHandler();
      fail(source, std::string("URDF parse failed: ") + e.what());
    }
    console_bridge::restorePreviousOutputHandler();
  }
  if (!urdf) {
    fail(source, "URDF parse failed" +
                     (capture.text().empty() ? std::string() : ": " + capture.text()));
  }
  if (!urdf->getRoot()) fail(source, "URDF has no root link");

  NaoModel model;
  std::map<std::string, int> link_index;

  // Depth-first from the root, children in NAO order: parents always come
  // before their children in links_ and joints_.
  std::vector<urdf::LinkConstSharedPtr> link_order;
  std::vector<urdf::JointConstSharedPtr> joint_order;
  std::vector<urdf::LinkConstSharedPtr> stack{urdf->getRoot()};
  while (!stack.empty()) {
    urdf::LinkConstSharedPtr l = stack.back();
    stack.pop_back();
    link_order.push_back(l);
    if (l->parent_joint) joint_order.push_back(l->parent_joint);
    std::vector<urdf::JointSharedPtr> kids = l->child_joints;
    std::sort(kids.begin(), kids.end(), [](const auto& a, const auto& b) {
      const double ka = orderKey(a->name), kb = orderKey(b->name);
      return ka != kb ? ka < kb : a->name < b->name;
    });
    // Pushed in reverse so the smallest key is visited first.
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) {
      urdf::LinkConstSharedPtr child = urdf->getLink((*it)->child_link_name);
      if (!child) fail(source, "joint '" + (*it)->name + "' has unknown child link");
      stack.push_back(child);
    }
  }
  if (link_order.size() != urdf->links_.size())
    fail(source, "links not connected to the root link '" + urdf->getRoot()->name + "'");

  for (const auto& l : link_order) {
    LinkSpec spec;
    spec.name = l->name;
    const std::string where = "link '" + l->name + "'";
    if (!l->inertial) fail(source, where + " has no <inertial> (mass and inertia are required)");
    spec.mass = l->inertial->mass;
    if (!std::isfinite(spec.mass) || spec.mass <= 0)
      fail(source, where + " has a non-positive or missing <mass> (" + std::to_string(spec.mass) + " kg)");
    spec.inertial_origin = toPose(l->inertial->origin);
    const auto& in = *l->inertial;
    spec.inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    if (!spec.inertia.allFinite()) fail(source, where + " has a non-finite inertia");
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(spec.inertia);
    if (eig.eigenvalues().minCoeff() <= 0)
      fail(source, where + " has an inertia tensor that is not positive definite");
    for (const auto& c : l->collision_array)
      if (c) spec.collisions.push_back(toShape(c->geometry, c->origin, true, source, l->name));
    for (const auto& v : l->visual_array) {
      if (!v) continue;
      ShapeSpec s = toShape(v->geometry, v->origin, false, source, l->name);
      urdf::MaterialSharedPtr mat = v->material;
      if (!mat && !v->material_name.empty()) mat = urdf->getMaterial(v->material_name);
      if (mat) s.rgba = Eigen::Vector4d(mat->color.r, mat->color.g, mat->color.b, mat->color.a);
      spec.visuals.push_back(s);
    }
    link_index[l->name] = static_cast<int>(model.links_.size());
    model.links_.push_back(std::move(spec));
  }
  model.root_ = 0;

  for (const auto& j : joint_order) {
    const std::string where = "joint '" + j->name + "'";
    if (j->type != urdf::Joint::REVOLUTE) {
      fail(source, where + " is not a hinge (type must be \"revolute\"; " +
                       (j->type == urdf::Joint::CONTINUOUS ? "continuous joints have no limits)" : "got another type)"));
    }
    if (!j->limits) fail(source, where + " has no <limit>");
    JointSpec spec;
    spec.name = j->name;
    spec.parent_link = link_index.at(j->parent_link_name);
    spec.child_link = link_index.at(j->child_link_name);
    spec.origin = toPose(j->parent_to_joint_origin_transform);
    spec.axis = Eigen::Vector3d(j->axis.x, j->axis.y, j->axis.z);
    if (!finite3(spec.axis) || spec.axis.norm() < 1e-9) fail(source, where + " has a zero or invalid <axis>");
    spec.axis.normalize();
    spec.lower = j->limits->lower;
    spec.upper = j->limits->upper;
    spec.max_velocity = j->limits->velocity;
    spec.max_effort = j->limits->effort;
    if (!std::isfinite(spec.lower) || !std::isfinite(spec.upper) || spec.lower > spec.upper)
      fail(source, where + ": <limit> lower (" + std::to_string(spec.lower) + ") > upper (" +
                       std::to_string(spec.upper) + ") rad");
    if (spec.lower < -M_PI || spec.upper > M_PI)
      fail(source, where + ": <limit> must lie within [-pi, pi] rad");
    if (!(spec.max_velocity > 0) || !std::isfinite(spec.max_velocity))
      fail(source, where + ": <limit velocity> must be positive (rad/s)");
    if (!(spec.max_effort > 0) || !std::isfinite(spec.max_effort))
      fail(source, where + ": <limit effort> must be positive (N*m)");
    if (j->mimic) {
      spec.mimic = j->mimic->joint_name;
      spec.mimic_multiplier = j->mimic->multiplier;
    }
    model.links_[spec.child_link].parent_joint = static_cast<int>(model.joints_.size());
    model.joints_.push_back(std::move(spec));
  }

  for (int i = 0; i < la::kNumJoints; ++i) {
    const int j = model.jointIndex(la::Joints::kNames[i]);
    if (j < 0) fail(source, std::string("missing joint '") + la::Joints::kNames[i] + "' (a libagent joint)");
    if (model.joints_[j].mimic)
      fail(source, std::string("joint '") + la::Joints::kNames[i] + "' is a libagent joint and cannot be a mimic");
    model.joints_[j].libagent_index = i;
    model.libagent_to_joint_[i] = j;
  }
  for (const auto& j : model.joints_) {
    if (!j.mimic) continue;
    const int target = model.jointIndex(*j.mimic);
    if (target < 0) fail(source, "joint '" + j.name + "' mimics unknown joint '" + *j.mimic + "'");
    if (model.joints_[target].mimic)
      fail(source, "joint '" + j.name + "' mimics '" + *j.mimic + "', which is itself a mimic");
  }

  return model;
}

int NaoModel::linkIndex(const std::string& name) const {
  for (size_t i = 0; i < links_.size(); ++i)
    if (links_[i].name == name) return static_cast<int>(i);
  return -1;
}

int NaoModel::jointIndex(const std::string& name) const {
  for (size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == name) return static_cast<int>(i);
  return -1;
}

double NaoModel::totalMass() const {
  double m = 0;
  for (const auto& l : links_) m += l.mass;
  return m;
}

std::vector<double> NaoModel::postureFromLibagent(const std::array<float, 25>& angles) const {
  std::vector<double> q(joints_.size(), 0.0);
  for (int i = 0; i < 25; ++i)
    if (libagent_to_joint_[i] >= 0) q[libagent_to_joint_[i]] = angles[i];
  for (size_t j = 0; j < joints_.size(); ++j)
    if (joints_[j].mimic) {
      const int leader = jointIndex(*joints_[j].mimic);
      if (leader >= 0) q[j] = joints_[j].mimic_multiplier * q[leader];
    }
  return q;
}

}  // namespace simswift
