#include "sim/experiment/TrialHooks.hpp"

#include <cmath>

#include "sim/camera/CameraModel.hpp"

namespace simswift::experiment {

void ScriptBehaviours::check(const Experiment& e, const ExperimentRobot& r) const {
  if (r.behaviour == Behaviour::Script) return;
  throw ConfigError(r.behaviour_where + ": " + behaviourName(r.behaviour) +
                    ": not built yet in this simswift (this build runs script robots only)");
}

void ScriptBehaviours::configure(const Experiment& e, const TrialSpec& t, runner::Scenario& sc) const {
  // trialScenario already copied each script robot's actions; nothing else
  // to set. (vision_yaml has no consumer until the vision oracle lands.)
  for (const ExperimentRobot& r : e.setups[t.setup].robots) check(e, r);
}

namespace {
int headLink(const NaoModel& m) {
  const int j = m.jointIndex("HeadPitch");
  return j < 0 ? -1 : m.joints()[j].child_link;
}
}  // namespace

double GroundTruthFoundRule::ballDistance(const World& w, int robot) {
  const RobotBody& body = w.robot(robot);
  const Eigen::Vector3d torso = body.linkPose(body.model().rootLink()).translation();
  const Eigen::Vector3d ball = w.ballPosition();
  return std::hypot(ball.x() - torso.x(), ball.y() - torso.y());
}

bool GroundTruthFoundRule::ballInView(const World& w, int robot) {
  const RobotBody& body = w.robot(robot);
  const int head = headLink(body.model());
  if (head < 0) return false;
  const Eigen::Isometry3d head_pose = body.linkPose(head);
  const Eigen::Vector3d ball = w.ballPosition();
  for (camera::CameraId id : {camera::kTop, camera::kBottom}) {
    const camera::CameraModel cam = camera::CameraModel::naoCamera(head_pose, id);
    const auto px = cam.project(ball);
    if (px && cam.inImage(*px)) return true;
  }
  return false;
}

int GroundTruthFoundRule::finder(const Experiment& e, runner::Runner& r) const {
  const World& w = r.world();
  for (int i = 0; i < w.numRobots(); ++i) {
    // Inclusive, as the thesis's "within 300mm (inclusive)"; 1 um slack for rounding.
    if (ballDistance(w, i) > e.found.distance + 1e-6) continue;
    if (e.found.sees && !ballInView(w, i)) continue;
    return i;
  }
  return -1;
}

TrialHooks defaultHooks() {
  TrialHooks h;
  h.behaviours = std::make_shared<ScriptBehaviours>();
  h.found = std::make_shared<GroundTruthFoundRule>();
  return h;
}

void checkBehaviours(const Experiment& e, const TrialHooks& hooks) {
  for (const Setup& s : e.setups)
    for (const ExperimentRobot& r : s.robots) hooks.behaviours->check(e, r);
}

}  // namespace simswift::experiment
