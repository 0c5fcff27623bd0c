// Tuning harness for the kick (run by hand: build/tools/kick-tuning). Kicks a
// ball placed as MotionPhysics.FullPowerKick* places it, on KICK_N seeds from
// KICK_SEED_BASE (default 900: tune on other seeds than the tests' 200-239),
// with the KickConfig fields overridden by KICK_<FIELD> (e.g. KICK_WIND_BACK=90,
// KICK_REACH, KICK_LIFT, KICK_SHIFT, KICK_HEIGHT, KICK_STRIKE_TIME_FAST,
// KICK_ARM_SWING, KICK_ANKLE_ROLL_MARGIN), KICK_POWER and KICK_DIRECTION (rad)
// for Distances. KICK_FOOT=left|right (default
// right). Distances prints a summary; Diagnose one line per kick (where the
// foot meets the ball, foot and ball speeds, the stance foot's slip and yaw,
// commands at a joint limit), and with KICK_TRACE a line per tick.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/runner/motion_harness.hpp"

using agent::blackboard::ActionType;
using agent::blackboard::Foot;
using motion_test::MotionHarness;

namespace {
void override(const char* name, double* field) {
  if (const char* e = std::getenv(name)) *field = std::atof(e);
}
void overrides(agent::motion::MotionConfig& cfg) {
  override("KICK_SHIFT", &cfg.kick.shift);
  override("KICK_HEIGHT", &cfg.kick.height);
  override("KICK_LIFT", &cfg.kick.lift);
  override("KICK_WIND_BACK", &cfg.kick.wind_back);
  override("KICK_REACH", &cfg.kick.reach);
  override("KICK_STRIKE_TIME_FAST", &cfg.kick.strike_time_fast);
  override("KICK_ARM_SWING", &cfg.kick.arm_swing);
  override("KICK_ANKLE_ROLL_MARGIN", &cfg.kick.ankle_roll_margin);
}
// Which kicks to run: KICK_FOOT (left|right, default right), KICK_N seeds
// (default 10) from KICK_SEED_BASE (default 900).
struct KickRuns {
  Foot foot;
  int n, base;
};
KickRuns kickRuns() {
  const char* foot_env = std::getenv("KICK_FOOT");
  return {foot_env && std::string(foot_env) == "left" ? Foot::LEFT : Foot::RIGHT,
          std::getenv("KICK_N") ? std::atoi(std::getenv("KICK_N")) : 10,
          std::getenv("KICK_SEED_BASE") ? std::atoi(std::getenv("KICK_SEED_BASE")) : 900};
}
}  // namespace

TEST(MotionKickTuning, Distances) {
  agent::motion::MotionConfig cfg;
  overrides(cfg);
  const KickRuns runs = kickRuns();
  const Foot foot = runs.foot;
  const int n = runs.n, base = runs.base;
  std::vector<double> d;
  int fell = 0;
  for (int s = base; s < base + n; ++s) {
    const double y = foot == Foot::RIGHT ? -0.05 : 0.05;
    MotionHarness h(static_cast<uint64_t>(s), -3.0, 0.0, 0.0,
                    "ball: {x: " + std::to_string(-3.0 + 0.17) + ", y: " + std::to_string(y) + "}\n", cfg);
    h.request(ActionType::STAND);
    h.run(1.0);
    const Eigen::Vector3d b0 = h.runner().world().ballPosition();
    const double power = std::getenv("KICK_POWER") ? std::atof(std::getenv("KICK_POWER")) : 1.0;
    const double direction = std::getenv("KICK_DIRECTION") ? std::atof(std::getenv("KICK_DIRECTION")) : 0.0;
    h.kick(foot, power, direction);
    if (!h.run(6.0)) ++fell;
    d.push_back((h.runner().world().ballPosition() - b0).head<2>().norm());
  }
  std::sort(d.begin(), d.end());
  const auto far = std::count_if(d.begin(), d.end(), [](double x) { return x >= 2.5; });
  std::printf("KICK %s n %d: >=2.5 m %ld, min %.2f median %.2f max %.2f, falls %d\n",
              foot == Foot::RIGHT ? "right" : "left", n, static_cast<long>(far), d.front(), d[d.size() / 2],
              d.back(), fell);
}

// Per-kick diagnosis (KICK_DIAG): where and how fast the foot meets the ball,
// what the stance foot and torso do meanwhile. One line per seed.
TEST(MotionKickTuning, Diagnose) {
  agent::motion::MotionConfig cfg;
  overrides(cfg);
  const KickRuns runs = kickRuns();
  const Foot foot = runs.foot;
  const int n = runs.n, base = runs.base;
  for (int s = base; s < base + n; ++s) {
    const double y = foot == Foot::RIGHT ? -0.05 : 0.05;
    MotionHarness h(static_cast<uint64_t>(s), -3.0, 0.0, 0.0,
                    "ball: {x: " + std::to_string(-3.0 + 0.17) + ", y: " + std::to_string(y) + "}\n", cfg);
    h.request(ActionType::STAND);
    h.run(1.0);
    auto& w = h.runner().world();
    const auto& body = w.robot(0);
    const int kick_link = body.model().linkIndex(foot == Foot::RIGHT ? "RFoot" : "LFoot");
    const int stance_link = body.model().linkIndex(foot == Foot::RIGHT ? "LFoot" : "RFoot");
    const int torso = body.model().rootLink();
    const Eigen::Vector3d b0 = w.ballPosition();
    const Eigen::Isometry3d st0 = body.linkPose(stance_link);
    h.kick(foot, 1.0, 0.0);
    double t_contact = -1, vmax = 0, vdir = 0, vz = 0, foot_vx = 0, foot_vy = 0, rel_y = 0, rel_z = 0, rel_x = 0;
    double st_dx = 0, st_dy = 0, st_yaw = 0, t_pitch = 0, t_roll = 0, max_pitch = 0, max_roll = 0;
    int contact_link = -1, contacts = 0;
    std::vector<int> at_limit;
    bool prev = false;
    bool up = true;
    const bool trace = std::getenv("KICK_TRACE") != nullptr;
    const int hp = body.model().jointIndex(foot == Foot::RIGHT ? "RHipPitch" : "LHipPitch");
    const int kn = body.model().jointIndex(foot == Foot::RIGHT ? "RKneePitch" : "LKneePitch");
    const int ap = body.model().jointIndex(foot == Foot::RIGHT ? "RAnklePitch" : "LAnklePitch");
    for (int i = 0; i < 600; ++i) {
      if (!h.run(0.01)) up = false;
      const double t = (i + 1) * 0.01;
      if (trace && t < 2.0) {
        const Eigen::Isometry3d sp = body.linkPose(stance_link), kp = body.linkPose(kick_link);
        const Eigen::Vector3d ax = sp.rotation().col(0), tx = body.linkPose(torso).rotation().col(0);
        const Eigen::Vector3d kv = body.linkLinearVelocity(kick_link, Eigen::Vector3d(0.03, 0.0, -0.038));
        const auto& cmd = h.checked().last_command.angles;
        namespace JJ = agent::libagent::Joints;
        const bool r = foot == Foot::RIGHT;
        double ground = 0;  // N on the kicking foot from the carpet
        for (const auto& c : w.contacts())
          if (c.robot == 0 && c.link == kick_link && c.other == simswift::GeomTag::Ground) ground += c.force.norm();
        const Eigen::Vector3d kw = body.linkAngularVelocity(kick_link);
        const int ar = body.model().jointIndex(foot == Foot::RIGHT ? "RAnkleRoll" : "LAnkleRoll");
        std::printf("ground %.0f N w(%.1f %.1f %.1f) aroll cmd %.3f sensed %.3f %.3f %.1f %.2fNm ", ground, kw.x(), kw.y(), kw.z(),
                    h.checked().last_command.angles[foot == Foot::RIGHT ? agent::libagent::Joints::RAnkleRoll : agent::libagent::Joints::LAnkleRoll],
                    h.checked().last_sensed.joints.angles[foot == Foot::RIGHT ? agent::libagent::Joints::RAnkleRoll : agent::libagent::Joints::LAnkleRoll],
                    body.jointAngle(ar),
                    body.jointVelocity(ar), body.jointTorque(ar));
        std::printf("t %.2f stance(%.1f %.1f yaw %.3f) torso yaw %.3f kick foot(%.3f %.3f %.3f) v %.2f | hip %.2f/%.2f %.1f knee %.2f/%.2f %.1f ankle %.2f/%.2f %.1f\n",
                    t, (sp.translation().x() - st0.translation().x()) * 1e3, (sp.translation().y() - st0.translation().y()) * 1e3,
                    std::atan2(ax.y(), ax.x()), std::atan2(tx.y(), tx.x()), kp.translation().x() + 3.0, kp.translation().y(),
                    kp.translation().z(), kv.x(), cmd[r ? JJ::RHipPitch : JJ::LHipPitch], body.jointAngle(hp), body.jointVelocity(hp),
                    cmd[r ? JJ::RKneePitch : JJ::LKneePitch], body.jointAngle(kn), body.jointVelocity(kn),
                    cmd[r ? JJ::RAnklePitch : JJ::LAnklePitch], body.jointAngle(ap), body.jointVelocity(ap));
      }
      bool touching = false;
      for (const auto& c : w.contacts())
        if (c.robot == 0 && c.other == simswift::GeomTag::Ball) {
          touching = true;
          if (t_contact < 0) {
            t_contact = t;
            contact_link = c.link;
            const Eigen::Isometry3d kp = body.linkPose(kick_link);
            const Eigen::Vector3d rel = kp.inverse() * c.position;
            rel_x = rel.x(); rel_y = rel.y(); rel_z = rel.z();
            const Eigen::Vector3d v = body.linkLinearVelocity(kick_link, Eigen::Vector3d(0.03, 0.0, -0.038));
            foot_vx = v.x(); foot_vy = v.y();
            const Eigen::Isometry3d sp = body.linkPose(stance_link);
            st_dx = sp.translation().x() - st0.translation().x();
            st_dy = sp.translation().y() - st0.translation().y();
            const Eigen::Vector3d ax = sp.rotation().col(0), ax0 = st0.rotation().col(0);
            st_yaw = std::atan2(ax.y(), ax.x()) - std::atan2(ax0.y(), ax0.x());
            const Eigen::Matrix3d R = body.linkPose(torso).rotation();
            t_pitch = std::asin(-R(2, 0));
            t_roll = std::atan2(R(2, 1), R(2, 2));
          }
        }
      {  // commands at a joint's limit while the kick runs (stiff joints only)
        const auto& lim = agent::motion::jointLimits();
        const auto& c = h.checked().last_command;
        if (h.state().posture == agent::blackboard::BodyState::KICKING)
          for (int j = 0; j < agent::libagent::kNumJoints; ++j)
            if (c.stiffnesses[j] > 0 && (c.angles[j] < lim[j].lower + 0.005 || c.angles[j] > lim[j].upper - 0.005)) {
              if (at_limit.empty() || at_limit.back() != j) at_limit.push_back(j);
            }
      }
      if (touching && !prev) ++contacts;
      prev = touching;
      const Eigen::Matrix3d R = body.linkPose(torso).rotation();
      max_pitch = std::max(max_pitch, std::fabs(std::asin(-R(2, 0))));
      max_roll = std::max(max_roll, std::fabs(std::atan2(R(2, 1), R(2, 2))));
      const Eigen::Vector3d bv = w.ballVelocity();
      if (t_contact > 0 && t < t_contact + 0.2 && bv.head<2>().norm() > vmax) {
        vmax = bv.head<2>().norm();
        vz = bv.z();
        vdir = std::atan2(bv.y(), bv.x());
      }
    }
    const double d = (w.ballPosition() - b0).head<2>().norm();
    std::sort(at_limit.begin(), at_limit.end());
    at_limit.erase(std::unique(at_limit.begin(), at_limit.end()), at_limit.end());
    for (int j : at_limit) std::printf("[at limit: joint %d] ", j);
    std::printf("seed %d d %.2f %s | contact t %.2f link %s n %d rel(%.3f %.3f %.3f) footv(%.2f %.2f) | ball v %.2f vz %.2f dir %.2f | "
                "stance d(%.1f %.1f)mm yaw %.3f | torso p %.3f r %.3f max p %.3f r %.3f\n",
                s, d, up ? "" : "FELL", t_contact, contact_link >= 0 ? body.model().links()[contact_link].name.c_str() : "-",
                contacts, rel_x, rel_y, rel_z, foot_vx, foot_vy, vmax, vz, vdir, st_dx * 1e3, st_dy * 1e3, st_yaw, t_pitch,
                t_roll, max_pitch, max_roll);
  }
}
