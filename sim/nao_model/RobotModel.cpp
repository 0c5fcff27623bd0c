// RobotModel: loads a URDF with urdfdom and checks it is a robot the
// simulator can build (every link has mass and a rigid body's inertia,
// every joint is a limited hinge, mimics follow a real leader). Whether it
// is a NAO libagent can drive is NaoBinding's check. Units as in
// RobotModel.hpp.
#include "sim/nao_model/RobotModel.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "common/libagent/AgentShared.hpp"  // the NAO's joint names, for the joint order only
#include "sim/nao_model/UrdfLines.hpp"

namespace simswift {

Eigen::Isometry3d Pose3::isometry() const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation.normalized().toRotationMatrix();
  t.translation() = xyz;
  return t;
}

namespace {

namespace la = common::libagent;

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

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw ModelError(source, line, what);
}

// Sane ranges for every number the loader accepts (SI units). Wide enough
// for any humanoid; narrow enough that nothing reaching ODE can overflow.
constexpr double kMaxOffset = 10.0;       // m: any origin component
constexpr double kMinMass = 1e-4;         // kg
constexpr double kMaxMass = 100.0;        // kg per link
constexpr double kMinInertia = 1e-12;     // kg*m^2, smallest principal moment
constexpr double kMaxInertia = 100.0;     // kg*m^2
constexpr double kMaxShapeSize = 10.0;    // m: box edge, radius, length
constexpr double kMaxAxisComponent = 1e6; // before normalising (no overflow in the norm)
constexpr double kMaxVelocity = 1e3;      // rad/s
constexpr double kMaxEffort = 1e4;        // N*m
constexpr double kMaxMimicMultiplier = 10.0;

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string vec(const Eigen::Vector3d& v) { return "(" + num(v.x()) + " " + num(v.y()) + " " + num(v.z()) + ")"; }

// "" if fine, else what is wrong with an <origin>.
std::string badPose(const urdf::Pose& p) {
  const Eigen::Vector3d xyz(p.position.x, p.position.y, p.position.z);
  if (!xyz.allFinite()) return "xyz " + vec(xyz) + " is not finite";
  if ((xyz.array().abs() > kMaxOffset).any())
    return "xyz " + vec(xyz) + " is more than " + num(kMaxOffset) + " m from the parent frame";
  const Eigen::Vector4d q(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  if (!q.allFinite()) return "rpy is not finite";
  return "";
}

Pose3 toPose(const urdf::Pose& p) {
  Pose3 out;
  out.xyz = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  out.rotation = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  if (out.rotation.norm() < 1e-9) out.rotation = Eigen::Quaterniond::Identity();
  out.rotation.normalize();
  return out;
}

bool sizeOk(double v) { return std::isfinite(v) && v > 0 && v <= kMaxShapeSize; }

ShapeSpec toShape(const urdf::GeometrySharedPtr& g, const urdf::Pose& origin, bool collision,
                  const std::string& source, int line, const std::string& link) {
  const std::string where = std::string(collision ? "<collision>" : "<visual>") + " of link '" + link + "'";
  if (!g) fail(source, line, where + " has no <geometry>");
  const std::string bad = badPose(origin);
  if (!bad.empty()) fail(source, line, where + " <origin>: " + bad);
  ShapeSpec s;
  s.origin = toPose(origin);
  const std::string range = " (must be > 0 and <= " + num(kMaxShapeSize) + " m)";
  switch (g->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*g);
      s.type = ShapeType::Box;
      s.size = Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z);
      if (!sizeOk(s.size.x()) || !sizeOk(s.size.y()) || !sizeOk(s.size.z()))
        fail(source, line, where + ": <box size> " + vec(s.size) + range);
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& sp = static_cast<const urdf::Sphere&>(*g);
      s.type = ShapeType::Sphere;
      s.radius = sp.radius;
      if (!sizeOk(s.radius)) fail(source, line, where + ": <sphere radius> " + num(s.radius) + range);
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
      if (!sizeOk(s.radius)) fail(source, line, where + ": <cylinder radius> " + num(s.radius) + range);
      if (!(s.length >= 0 && s.length <= kMaxShapeSize))
        fail(source, line, where + ": <cylinder length> " + num(s.length) + " (must be >= 0 and <= " +
                               num(kMaxShapeSize) + " m)");
      break;
    }
    case urdf::Geometry::MESH: {
      if (collision)
        fail(source, line, where + ": mesh collision geometry is not supported (use box/sphere/cylinder)");
      const auto& m = static_cast<const urdf::Mesh&>(*g);
      s.type = ShapeType::Mesh;
      s.mesh = m.filename;
      s.size = Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z);
      if (!s.size.allFinite() || (s.size.array().abs() > 1e3).any())
        fail(source, line, where + ": <mesh scale> " + vec(s.size) + " must be finite and at most 1000");
      break;
    }
    default:
      fail(source, line, where + ": unknown geometry type");
  }
  return s;
}

// Position of a joint in the NAO's 26-joint order (libagent order with
// RHipYawPitch just before RHipRoll); used to give links and joints a stable,
// familiar order instead of urdfdom's alphabetical maps. Any other model's
// joints sort by name.
double orderKey(const std::string& name) {
  for (int i = 0; i < la::kNumJoints; ++i)
    if (name == la::Joints::kNames[i]) return i;
  if (name == "RHipYawPitch") return la::Joints::RHipRoll - 0.5;
  return 1000.0;  // anything else after, alphabetically (ties keep name order)
}

// urdfdom's links hold their children by shared_ptr, so a kinematic loop
// in a malformed file (the fuzzer's: two <child> lines swapped) is a
// cycle nothing would free. Breaks it however the loader ends.
struct BreakLinkCycles {
  urdf::ModelInterfaceSharedPtr& model;
  ~BreakLinkCycles() {
    if (!model) return;
    for (auto& named : model->links_) {
      named.second->child_links.clear();
      named.second->child_joints.clear();
    }
  }
};

// Parses `xml` with urdfdom into `urdf` (the caller's, so its cycles are
// broken whatever fails here), quoting urdfdom's own complaints.
void parseWithUrdfdom(const std::string& xml, const std::string& source, const UrdfLines& lines,
                      urdf::ModelInterfaceSharedPtr& urdf) {
  CaptureHandler capture;
  {
    std::lock_guard<std::mutex> lock(parserMutex());
    console_bridge::useOutputHandler(&capture);
    try {
      urdf = urdf::parseURDF(xml);
    } catch (const std::exception& e) {
      console_bridge::restorePreviousOutputHandler();
      const std::string what = e.what();
      fail(source, lines.lineMentioned(capture.text() + " " + what), "URDF parse failed: " + what);
    }
    console_bridge::restorePreviousOutputHandler();
  }
  if (!urdf) {
    fail(source, lines.lineMentioned(capture.text()),
         "URDF parse failed" + (capture.text().empty() ? std::string() : ": " + capture.text()));
  }
  if (!urdf->getRoot()) fail(source, lines.robot(), "URDF has no root link");
}

struct TreeOrder {
  std::vector<urdf::LinkConstSharedPtr> links;
  std::vector<urdf::JointConstSharedPtr> joints;  // each link's parent joint, the root's none
};

// Depth-first from the root, children in NAO order: parents always come
// before their children in links_ and joints_.
TreeOrder treeOrder(const urdf::ModelInterface& urdf, const std::string& source, const UrdfLines& lines) {
  TreeOrder order;
  std::vector<urdf::LinkConstSharedPtr> stack{urdf.getRoot()};
  while (!stack.empty()) {
    urdf::LinkConstSharedPtr l = stack.back();
    stack.pop_back();
    order.links.push_back(l);
    if (l->parent_joint) order.joints.push_back(l->parent_joint);
    std::vector<urdf::JointSharedPtr> kids = l->child_joints;
    std::sort(kids.begin(), kids.end(), [](const auto& a, const auto& b) {
      const double ka = orderKey(a->name), kb = orderKey(b->name);
      return ka != kb ? ka < kb : a->name < b->name;
    });
    // Pushed in reverse so the smallest key is visited first.
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) {
      urdf::LinkConstSharedPtr child = urdf.getLink((*it)->child_link_name);
      if (!child) fail(source, lines.joint((*it)->name), "joint '" + (*it)->name + "' has unknown child link");
      stack.push_back(child);
    }
  }
  if (order.links.size() != urdf.links_.size())
    fail(source, lines.robot(), "links not connected to the root link '" + urdf.getRoot()->name + "'");
  return order;
}

// The link's mass, centre of mass and inertia: a rigid body's, in range.
void readInertial(const urdf::Link& l, const std::string& source, const UrdfLines& lines, LinkSpec& spec) {
  const std::string where = "link '" + l.name + "'";
  auto at = [&](const char* path) { return lines.linkChild(l.name, path); };
  if (!l.inertial) fail(source, lines.link(l.name), where + " has no <inertial> (mass and inertia are required)");
  if (!lines.linkHas(l.name, "inertial/mass"))
    fail(source, at("inertial"), where + " has no <mass> in its <inertial>");
  spec.mass = l.inertial->mass;
  if (!std::isfinite(spec.mass) || spec.mass < kMinMass || spec.mass > kMaxMass)
    fail(source, at("inertial/mass"), where + " <mass value> " + num(spec.mass) + " kg (must be in [" +
                                          num(kMinMass) + ", " + num(kMaxMass) + "] kg)");
  const std::string bad_origin = badPose(l.inertial->origin);
  if (!bad_origin.empty()) fail(source, at("inertial/origin"), where + " <inertial><origin>: " + bad_origin);
  spec.inertial_origin = toPose(l.inertial->origin);
  const auto& in = *l.inertial;
  if (!lines.linkHas(l.name, "inertial/inertia"))
    fail(source, at("inertial"), where + " has no <inertia> in its <inertial>");
  spec.inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  if (!spec.inertia.allFinite()) fail(source, at("inertial/inertia"), where + " <inertia> has a value that is not finite");
  if ((spec.inertia.array().abs() > kMaxInertia).any())
    fail(source, at("inertial/inertia"), where + " <inertia> has a value beyond " + num(kMaxInertia) + " kg*m^2");
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(spec.inertia);
  const Eigen::Vector3d ev = eig.eigenvalues();  // ascending
  if (ev.minCoeff() < kMinInertia)
    fail(source, at("inertial/inertia"), where + " <inertia> is not positive definite (principal moments " +
                                             vec(ev) + " kg*m^2; each must be >= " + num(kMinInertia) + ")");
  // A rigid body's principal moments obey the triangle inequality.
  if (ev(0) + ev(1) < ev(2) * (1 - 1e-6))
    fail(source, at("inertial/inertia"), where + " <inertia> is not a rigid body's (principal moments " +
                                             vec(ev) + " kg*m^2 break I1 + I2 >= I3)");
}

// The link's <collision> and <visual> shapes (visuals with their material's colour).
void readShapes(const urdf::ModelInterface& urdf, const urdf::Link& l, const std::string& source,
                const UrdfLines& lines, LinkSpec& spec) {
  // urdfdom drops a <collision> it cannot parse; count them ourselves.
  size_t ci = 0;
  for (const auto& c : l.collision_array) {
    if (!c) continue;
    spec.collisions.push_back(toShape(c->geometry, c->origin, true, source, lines.collision(l.name, ci), l.name));
    ++ci;
  }
  if (spec.collisions.size() != lines.collisionCount(l.name))
    fail(source, lines.collision(l.name, spec.collisions.size()),
         "link '" + l.name + "': a <collision> could not be read (bad or missing <geometry> or <origin>)");
  for (const auto& v : l.visual_array) {
    if (!v) continue;
    ShapeSpec s = toShape(v->geometry, v->origin, false, source, lines.linkChild(l.name, "visual"), l.name);
    urdf::MaterialSharedPtr mat = v->material;
    if (!mat && !v->material_name.empty()) mat = urdf.getMaterial(v->material_name);
    if (mat) {
      s.rgba = Eigen::Vector4d(mat->color.r, mat->color.g, mat->color.b, mat->color.a);
      if (!s.rgba.allFinite()) s.rgba = Eigen::Vector4d(0.8, 0.8, 0.8, 1.0);
      s.rgba = s.rgba.cwiseMax(0.0).cwiseMin(1.0);
    }
    spec.visuals.push_back(s);
  }
}

LinkSpec readLink(const urdf::ModelInterface& urdf, const urdf::Link& l, const std::string& source,
                  const UrdfLines& lines) {
  LinkSpec spec;
  spec.name = l.name;
  readInertial(l, source, lines, spec);
  readShapes(urdf, l, source, lines, spec);
  return spec;
}

// The joint's <limit>: finite, ordered, within [-pi, pi], sane speed and effort.
void readLimits(const urdf::Joint& j, const std::string& source, const UrdfLines& lines, JointSpec& spec) {
  const std::string where = "joint '" + j.name + "'";
  spec.lower = j.limits->lower;
  spec.upper = j.limits->upper;
  spec.max_velocity = j.limits->velocity;
  spec.max_effort = j.limits->effort;
  const int limit_line = lines.jointChild(j.name, "limit");
  if (!std::isfinite(spec.lower) || !std::isfinite(spec.upper) || spec.lower > spec.upper)
    fail(source, limit_line, where + ": <limit> lower (" + num(spec.lower) + ") > upper (" + num(spec.upper) +
                                 ") rad, or not finite");
  if (spec.lower < -M_PI || spec.upper > M_PI)
    fail(source, limit_line, where + ": <limit> must lie within [-pi, pi] rad");
  if (!(spec.max_velocity > 0) || !(spec.max_velocity <= kMaxVelocity))
    fail(source, limit_line, where + ": <limit velocity> " + num(spec.max_velocity) + " must be in (0, " +
                                 num(kMaxVelocity) + "] rad/s");
  if (!(spec.max_effort > 0) || !(spec.max_effort <= kMaxEffort))
    fail(source, limit_line, where + ": <limit effort> " + num(spec.max_effort) + " must be in (0, " +
                                 num(kMaxEffort) + "] N*m");
}

// `link_index`: link name -> index in the model's links (all read before).
JointSpec readJoint(const urdf::Joint& j, const std::map<std::string, int>& link_index, const std::string& source,
                    const UrdfLines& lines) {
  const std::string where = "joint '" + j.name + "'";
  auto at = [&](const char* path) { return lines.jointChild(j.name, path); };
  if (j.type != urdf::Joint::REVOLUTE) {
    fail(source, lines.joint(j.name), where + " is not a hinge (type must be \"revolute\"; " +
                     (j.type == urdf::Joint::CONTINUOUS ? "continuous joints have no limits)" : "got another type)"));
  }
  if (!j.limits) fail(source, lines.joint(j.name), where + " has no <limit>");
  JointSpec spec;
  spec.name = j.name;
  spec.line = lines.joint(j.name);
  spec.mimic_line = at("mimic");
  spec.parent_link = link_index.at(j.parent_link_name);
  spec.child_link = link_index.at(j.child_link_name);
  const std::string bad_origin = badPose(j.parent_to_joint_origin_transform);
  if (!bad_origin.empty()) fail(source, at("origin"), where + " <origin>: " + bad_origin);
  spec.origin = toPose(j.parent_to_joint_origin_transform);
  spec.axis = Eigen::Vector3d(j.axis.x, j.axis.y, j.axis.z);
  // Each component bounded before the norm, so the norm cannot overflow.
  if (!spec.axis.allFinite() || (spec.axis.array().abs() > kMaxAxisComponent).any() || spec.axis.norm() < 1e-6)
    fail(source, at("axis"), where + " <axis xyz> " + vec(spec.axis) +
                                 " must be a non-zero finite direction (components within 1e6)");
  spec.axis.normalize();
  readLimits(j, source, lines, spec);
  if (j.mimic) {
    spec.mimic = j.mimic->joint_name;
    spec.mimic_multiplier = j.mimic->multiplier;
    if (!std::isfinite(spec.mimic_multiplier) || std::fabs(spec.mimic_multiplier) > kMaxMimicMultiplier)
      fail(source, at("mimic"), where + " <mimic multiplier> " + num(spec.mimic_multiplier) + " must be within +-" +
                                    num(kMaxMimicMultiplier));
  }
  return spec;
}

// Every mimic follows a joint of the model that is not itself a mimic.
void checkMimics(const RobotModel& model, const std::string& source) {
  for (const auto& j : model.joints()) {
    if (!j.mimic) continue;
    const int target = model.jointIndex(*j.mimic);
    if (target < 0)
      fail(source, j.mimic_line, "missing joint '" + *j.mimic + "' (joint '" + j.name + "' mimics it)");
    if (model.joints()[target].mimic)
      fail(source, j.mimic_line, "joint '" + j.name + "' mimics '" + *j.mimic + "', which is itself a mimic");
  }
}

}  // namespace

RobotModel RobotModel::loadUrdf(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ModelError(path, 1, "is a directory, not a URDF file");
  std::ifstream in(path);
  if (!in) throw ModelError(path, 1, "cannot open URDF file");
  // Refuse a huge file before reading it all.
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > UrdfLimits::kMaxBytes)
    throw ModelError(path, 1,
                     "URDF is " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(UrdfLimits::kMaxBytes >> 20) + " MB limit");
  std::stringstream ss;
  ss << in.rdbuf();
  return loadUrdfString(ss.str(), path);
}

RobotModel RobotModel::loadUrdfString(const std::string& xml, const std::string& source) {
  // Size, depth and XML syntax first (cheap, and urdfdom's parser would
  // overflow the stack on deep nesting); then lines for every message.
  const UrdfLines lines(xml, source);
  urdf::ModelInterfaceSharedPtr urdf;
  const BreakLinkCycles break_cycles{urdf};
  parseWithUrdfdom(xml, source, lines, urdf);
  const TreeOrder order = treeOrder(*urdf, source, lines);

  RobotModel model;
  model.source_ = source;
  model.robot_line_ = lines.robot();
  std::map<std::string, int> link_index;
  for (const auto& l : order.links) {
    LinkSpec spec = readLink(*urdf, *l, source, lines);
    link_index[l->name] = static_cast<int>(model.links_.size());
    model.links_.push_back(std::move(spec));
  }
  model.root_ = 0;
  for (const auto& j : order.joints) {
    JointSpec spec = readJoint(*j, link_index, source, lines);
    model.links_[spec.child_link].parent_joint = static_cast<int>(model.joints_.size());
    model.joints_.push_back(std::move(spec));
  }
  checkMimics(model, source);
  return model;
}

int RobotModel::linkIndex(const std::string& name) const {
  for (size_t i = 0; i < links_.size(); ++i)
    if (links_[i].name == name) return static_cast<int>(i);
  return -1;
}

int RobotModel::jointIndex(const std::string& name) const {
  for (size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == name) return static_cast<int>(i);
  return -1;
}

double RobotModel::totalMass() const {
  double m = 0;
  for (const auto& l : links_) m += l.mass;
  return m;
}

}  // namespace simswift
