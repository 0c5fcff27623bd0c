// Tuning harness for the get-up keyframes, run by hand (build/tools/getup-tuning;
// never by ctest). Pushes the robot over and prints, every 0.1 s, the time,
// the Motion mode, torso height (m), AngleX / AngleY (rad), the get-up
// attempts and the main joints' sensed/commanded angles (--torque: also each
// left joint's torque over its stall torque), then one line
//   RESULT <front|back> trial N: UP|down up_at T attempts A best R besth H
// (--quiet: that line only). scripts/getup_tuning.py drives it.
//
//   getup-tuning [--dir front|back] [--frames FILE] [--trial N] [--seed-base S]
//                [--one] [--quiet] [--roll] [--torque]
//
// --frames FILE replaces the front (--dir front, the default) or back
// sequence with keyframes read from a text file, so sequences can be tuned
// without a rebuild. Line format (rad, s; symmetric arms/legs as in Generators.cpp):
//   dur sp sr ey er hyp hr hp kn ap ar [joint=value ...]
//   crouch dur | stand dur | front (the front get-up's frames)
// --trial N: the push (and the noise seed's offset); --seed-base S: the noise
// seed base (default 100 front, 150 back: the tests'); --one: stop after the
// first attempt; --roll: score the chest facing down.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/runner/FallDetector.hpp"
#include "harness/MotionHarness.hpp"

using agent::blackboard::ActionType;
using motion_test::MotionHarness;
namespace J = common::libagent::Joints;
namespace S = common::libagent::Sensors;

namespace {

struct Options {
  bool forwards = true;     // --dir front (back: false)
  std::string frames;       // --frames
  int trial = 0;            // --trial
  int base = -1;            // --seed-base (-1: the tests' for the direction)
  bool one = false, quiet = false, roll = false, torque = false;
};

// --help: the usage on stdout, exit 0; a bad argument: why and the usage on stderr, exit 2.
[[noreturn]] void usage(const std::string& why, int code = 2) {
  std::fprintf(code == 0 ? stdout : stderr,
               "getup-tuning: %s\nusage: getup-tuning [--dir front|back] [--frames FILE] [--trial N] "
               "[--seed-base S] [--one] [--quiet] [--roll] [--torque]\n",
               why.c_str());
  std::exit(code);
}

int integer(const std::string& flag, const char* text) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0') usage(flag + ": not an integer: '" + text + "'");
  return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "--dir") {
      const std::string d = value();
      if (d != "front" && d != "back") usage("--dir: front or back (got '" + d + "')");
      o.forwards = d == "front";
    } else if (a == "--frames") {
      o.frames = value();
      if (!std::ifstream(o.frames)) usage("--frames: cannot read " + o.frames);
    } else if (a == "--trial") {
      o.trial = integer(a, value());
    } else if (a == "--seed-base") {
      o.base = integer(a, value());
    } else if (a == "--one") {
      o.one = true;
    } else if (a == "--quiet") {
      o.quiet = true;
    } else if (a == "--roll") {
      o.roll = true;
    } else if (a == "--torque") {
      o.torque = true;
    } else if (a == "--help" || a == "-h") {
      usage("the get-ups' tuning harness", 0);
    } else {
      usage("unknown argument '" + a + "'");
    }
  }
  return o;
}

std::vector<agent::motion::Keyframe> readFrames(const std::string& path, const agent::motion::WalkConfig& cfg) {
  std::vector<agent::motion::Keyframe> f;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string first;
    ls >> first;
    if (first == "front") {  // the whole front get-up, e.g. after a roll onto the front
      const auto front = agent::motion::getupFrontFrames(cfg);
      f.insert(f.end(), front.begin(), front.end());
      continue;
    }
    if (first == "crouch" || first == "stand") {
      double d;
      ls >> d;
      f.push_back({d, first == "crouch" ? agent::motion::crouchAngles() : agent::motion::walkStandAngles(cfg), 1.0f});
      continue;
    }
    double d = std::stod(first);
    float v[10];
    for (float& x : v) ls >> x;
    agent::motion::JointArray a{};
    a[J::LShoulderPitch] = a[J::RShoulderPitch] = v[0];
    a[J::LShoulderRoll] = v[1];
    a[J::RShoulderRoll] = -v[1];
    a[J::LElbowYaw] = v[2];
    a[J::RElbowYaw] = -v[2];
    a[J::LElbowRoll] = v[3];
    a[J::RElbowRoll] = -v[3];
    a[J::LHipYawPitch] = v[4];
    a[J::LHipRoll] = v[5];
    a[J::RHipRoll] = -v[5];
    a[J::LHipPitch] = a[J::RHipPitch] = v[6];
    a[J::LKneePitch] = a[J::RKneePitch] = v[7];
    a[J::LAnklePitch] = a[J::RAnklePitch] = v[8];
    a[J::LAnkleRoll] = v[9];
    a[J::RAnkleRoll] = -v[9];
    std::string kv;
    while (ls >> kv) {
      const auto eq = kv.find('=');
      a[std::stoi(kv.substr(0, eq))] = std::stof(kv.substr(eq + 1));
    }
    f.push_back({d, a, 1.0f});
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const bool forwards = o.forwards;
  const int trial = o.trial;
  const bool quiet = o.quiet;
  agent::motion::MotionConfig cfg;
  if (!o.frames.empty()) (forwards ? cfg.getup_front : cfg.getup_back) = readFrames(o.frames, cfg.walk);
  // --seed-base: tune on other noise seeds than the test's (100 front, 150 back).
  const int base = o.base >= 0 ? o.base : (forwards ? 100 : 150);
  MotionHarness h(base + trial, -3.0, 0.0, 0.0, "", cfg);
  h.request(ActionType::STAND);
  h.run(1.0);
  const double dv = 3.0 + 0.1 * trial;
  h.push(forwards ? dv : -dv, 0.02 * (trial - 5));
  bool fell = false;
  double up_at = -1, best = -9, best_h = 0;
  bool face_down = false;  // the first attempt has had the chest down (a back roll worked)
  std::vector<double> window, window_h;
  const bool one = o.one;  // stop after the first attempt
  for (int i = 0; i < 1300; ++i) {
    h.run(0.01);
    const auto st = h.state();
    if (motion_test::downOrGettingUp(st.posture)) fell = true;
    const float* s = h.checked().last_sensed.sensors;
    // Progress of the first attempt: high and upright is good.
    if (h.motion().getupAttempts() == 1 && h.motion().mode() == agent::motion::ActionMotion::Mode::Getup)
    {
      // Held for 0.5 s (the minimum over the last 50 ticks), so a throw that falls back does not count.
      // --roll scores how far the chest faces down (the torso x axis against
      // world z: -1 on the back, 0 on the side or sitting, +1 face down).
      const auto& robot = h.runner().world().robot(0);
      const double chest_down = -robot.linkPose(robot.model().rootLink()).rotation().col(0).z();
      window.push_back(o.roll ? chest_down
                                                 : h.torsoHeight() - 0.2 * std::fabs(s[S::InertialSensor_AngleY]) -
                                                       0.2 * std::fabs(s[S::InertialSensor_AngleX]));
      if (window.size() > 50) window.erase(window.begin());
      if (window.size() == 50) best = std::max(best, *std::min_element(window.begin(), window.end()));
      // After a roll onto the front: how high the torso then rises (held 0.5 s, m).
      face_down = face_down || chest_down > 0.9;
      if (face_down) window_h.push_back(h.torsoHeight());
      if (window_h.size() > 50) window_h.erase(window_h.begin());
      if (window_h.size() == 50) best_h = std::max(best_h, *std::min_element(window_h.begin(), window_h.end()));
    }
    if (one && h.motion().getupAttempts() >= 1 && h.motion().mode() != agent::motion::ActionMotion::Mode::Getup &&
        !(fell && st.posture == agent::blackboard::BodyState::STANDING))
      break;
    if (!quiet && i % 10 == 0)
    {
      const float* q = h.checked().last_sensed.joints.angles;
      const float* c = h.checked().last_command.angles;
      std::printf("t %5.2f m%d h %.3f ax %+.2f ay %+.2f a%d | sp %+.2f/%+.2f er %+.2f/%+.2f hyp %+.2f/%+.2f hp %+.2f/%+.2f kn %+.2f/%+.2f ap %+.2f/%+.2f\n",
                  i * 0.01, static_cast<int>(h.motion().mode()), h.torsoHeight(), s[S::InertialSensor_AngleX],
                  s[S::InertialSensor_AngleY], h.motion().getupAttempts(), q[J::LShoulderPitch], c[J::LShoulderPitch],
                  q[J::LElbowRoll], c[J::LElbowRoll], q[J::LHipYawPitch], c[J::LHipYawPitch], q[J::LHipPitch],
                  c[J::LHipPitch], q[J::LKneePitch], c[J::LKneePitch], q[J::LAnklePitch], c[J::LAnklePitch]);
      if (o.torque) {
        // Torque delivered / the motor's cap at rest (stall x efficiency x stiffness), per left joint.
        const auto& robot = h.runner().world().robot(0);
        std::printf("        torque/stall:");
        for (const char* name : {"LShoulderPitch", "LShoulderRoll", "LElbowRoll", "LHipYawPitch", "LHipRoll",
                                 "LHipPitch", "LKneePitch", "LAnklePitch"}) {
          const int j = robot.model().jointIndex(name);
          const auto& lim = robot.servos().limits(j);
          const double stall = lim.max_effort * robot.servos().config().gear_efficiency;
          std::printf(" %s %+.2f", name + 1, robot.jointTorque(j) / stall);
        }
        std::printf("\n");
      }
    }
    if (fell && st.posture == agent::blackboard::BodyState::STANDING && h.torsoHeight() > simswift::runner::FallDetector::kStandHeight) {
      up_at = i * 0.01;
      break;
    }
  }
  std::printf("RESULT %s trial %d: %s up_at %.2f attempts %d best %.3f besth %.3f\n", forwards ? "front" : "back",
              trial, up_at >= 0 ? "UP" : "down", up_at, h.motion().getupAttempts(), best, best_h);
  return 0;
}
