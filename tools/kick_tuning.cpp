// Tuning harness for the kick, run by hand (build/tools/kick-tuning; never
// by ctest). Kicks a ball placed as MotionPhysics.FullPowerKick* places it,
// on --n seeds from --seed-base (default 900: tune on other seeds than the
// tests' 200-239), with KickConfig fields overridden by --kick FIELD=VALUE
// (shift, height, lift, wind_back, reach, strike_time_fast, arm_swing,
// ankle_roll_margin; repeatable).
//
//   kick-tuning [distances|diagnose] [--foot left|right] [--n N] [--seed-base S]
//               [--power P] [--direction RAD] [--kick FIELD=VALUE ...] [--trace]
//
// distances prints one summary line (kicks of >= 2.5 m, the min, median and
// max distance, falls), with --power and --direction (rad) for its kicks;
// diagnose one line per kick (where the foot meets the ball, foot and ball
// speeds, the stance foot's slip and yaw, commands at a joint limit), and
// with --trace a line per tick. Neither named: both, distances first.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "harness/MotionHarness.hpp"

using agent::blackboard::ActionType;
using agent::blackboard::Foot;
using motion_test::MotionHarness;

namespace {

struct Options {
  bool distances = true, diagnose = true;
  Foot foot = Foot::RIGHT;
  int n = 10, base = 900;
  double power = 1.0, direction = 0.0;  // distances' kicks (diagnose: full power, straight)
  bool trace = false;
  agent::motion::MotionConfig cfg;
};

// --help: the usage on stdout, exit 0; a bad argument: why and the usage on stderr, exit 2.
[[noreturn]] void usage(const std::string& why, int code = 2) {
  std::fprintf(code == 0 ? stdout : stderr,
               "kick-tuning: %s\nusage: kick-tuning [distances|diagnose] [--foot left|right] [--n N] "
               "[--seed-base S] [--power P] [--direction RAD] [--kick FIELD=VALUE ...] [--trace]\n",
               why.c_str());
  std::exit(code);
}

double number(const std::string& flag, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v)) usage(flag + ": not a number: '" + text + "'");
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  agent::motion::KickConfig& k = o.cfg.kick;
  const std::map<std::string, double*> fields = {
      {"shift", &k.shift},         {"height", &k.height},
      {"lift", &k.lift},           {"wind_back", &k.wind_back},
      {"reach", &k.reach},         {"strike_time_fast", &k.strike_time_fast},
      {"arm_swing", &k.arm_swing}, {"ankle_roll_margin", &k.ankle_roll_margin}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "distances" || a == "diagnose") {
      o.distances = a == "distances";
      o.diagnose = a == "diagnose";
    } else if (a == "--foot") {
      const std::string f = value();
      if (f != "left" && f != "right") usage("--foot: left or right (got '" + f + "')");
      o.foot = f == "left" ? Foot::LEFT : Foot::RIGHT;
    } else if (a == "--n") {
      o.n = static_cast<int>(number(a, value()));
      if (o.n < 1) usage("--n: at least 1 kick");
    } else if (a == "--seed-base") {
      o.base = static_cast<int>(number(a, value()));
    } else if (a == "--power") {
      o.power = number(a, value());
    } else if (a == "--direction") {
      o.direction = number(a, value());
    } else if (a == "--kick") {
      const std::string kv = value();
      const size_t eq = kv.find('=');
      const auto it = fields.find(kv.substr(0, eq));
      if (eq == std::string::npos || it == fields.end()) {
        std::string names;
        for (const auto& f : fields) names += (names.empty() ? "" : ", ") + f.first;
        usage("--kick: FIELD=VALUE with FIELD one of " + names + " (got '" + kv + "')");
      }
      *it->second = number("--kick " + it->first, kv.c_str() + eq + 1);
    } else if (a == "--trace") {
      o.trace = true;
    } else if (a == "--help" || a == "-h") {
      usage("the kick's tuning harness", 0);
    } else {
      usage("unknown argument '" + a + "'");
    }
  }
  return o;
}

// Distance of each kick: one summary line.
void distances(const Options& o) {
  const agent::motion::MotionConfig& cfg = o.cfg;
  const Foot foot = o.foot;
  const int n = o.n, base = o.base;
  std::vector<double> d;
  int fell = 0;
  for (int s = base; s < base + n; ++s) {
    const double y = foot == Foot::RIGHT ? -0.05 : 0.05;
    MotionHarness h(static_cast<uint64_t>(s), -3.0, 0.0, 0.0,
                    "ball: {x: " + std::to_string(-3.0 + 0.17) + ", y: " + std::to_string(y) + "}\n", cfg);
    h.request(ActionType::STAND);
    h.run(1.0);
    const Eigen::Vector3d b0 = h.runner().world().ballPosition();
    h.kick(foot, o.power, o.direction);
    if (!h.run(6.0)) ++fell;
    d.push_back((h.runner().world().ballPosition() - b0).head<2>().norm());
  }
  std::sort(d.begin(), d.end());
  const auto far = std::count_if(d.begin(), d.end(), [](double x) { return x >= 2.5; });
  std::printf("KICK %s n %d: >=2.5 m %ld, min %.2f median %.2f max %.2f, falls %d\n",
              foot == Foot::RIGHT ? "right" : "left", n, static_cast<long>(far), d.front(), d[d.size() / 2],
              d.back(), fell);
}

// Per-kick diagnosis: where and how fast the foot meets the ball, what the
// stance foot and torso do meanwhile. One line per seed.
void diagnose(const Options& o) {
  const agent::motion::MotionConfig& cfg = o.cfg;
  const Foot foot = o.foot;
  const int n = o.n, base = o.base;
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
    const bool trace = o.trace;
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
        namespace JJ = common::libagent::Joints;
        const bool r = foot == Foot::RIGHT;
        double ground = 0;  // N on the kicking foot from the carpet
        for (const auto& c : w.contacts())
          if (c.robot == 0 && c.link == kick_link && c.other == simswift::GeomTag::Ground) ground += c.force.norm();
        const Eigen::Vector3d kw = body.linkAngularVelocity(kick_link);
        const int ar = body.model().jointIndex(foot == Foot::RIGHT ? "RAnkleRoll" : "LAnkleRoll");
        std::printf("ground %.0f N w(%.1f %.1f %.1f) aroll cmd %.3f sensed %.3f %.3f %.1f %.2fNm ", ground, kw.x(), kw.y(), kw.z(),
                    h.checked().last_command.angles[foot == Foot::RIGHT ? common::libagent::Joints::RAnkleRoll : common::libagent::Joints::LAnkleRoll],
                    h.checked().last_sensed.joints.angles[foot == Foot::RIGHT ? common::libagent::Joints::RAnkleRoll : common::libagent::Joints::LAnkleRoll],
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
          for (int j = 0; j < common::libagent::kNumJoints; ++j)
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

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.distances) distances(o);
  if (o.diagnose) diagnose(o);
  return 0;
}
