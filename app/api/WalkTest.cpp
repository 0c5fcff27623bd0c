// The walk test kit (include/simswift/WalkTest.hpp): WalkMeter, the one home
// of the walk's achieved / commanded, heading drift, falls and stance slip
// (bench_motion and the motion tests use it too); WalkTest, a simulation
// whose robot a team's gait drives through the controller path; the trace
// (CSV) and its plot (gnuplot); the reference walk as a Gait.
#include "simswift/WalkTest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#include "common/libagent/AgentShared.hpp"
#include "common/nao/NaoFacts.hpp"
#include "sim/programs/ReferenceWalk.hpp"
#include "app/api/SimulationAccess.hpp"
#include "app/api/WalkSampling.hpp"
#include "app/experiment/Figures.hpp"

namespace simswift::api {

namespace {

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

// The stance rule (WalkFigures::stances):
constexpr double kStanceShare = 0.7;  // a foot carrying more than this share of the feet's force
constexpr double kStanceMinN = 10.0;  // N the feet carry together, at least

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

// --- WalkMeter ----------------------------------------------------------------

void WalkMeter::begin(const WalkSample& start, const WalkCommand& commanded) {
  *this = WalkMeter();
  commanded_ = commanded;
  start_ = last_ = start;
  begun_ = true;
}

void WalkMeter::add(const WalkSample& s) {
  if (!begun_) throw std::logic_error("WalkMeter::add before begin");
  turned_ += wrap(s.torso.theta - last_.torso.theta);
  const double t = s.t - start_.t;
  n_ += 1, st_ += t, sy_ += turned_, stt_ += t * t, sty_ += t * turned_;
  const double total = s.feet[0].force + s.feet[1].force;  // N
  for (int k = 0; k < 2; ++k) {
    const bool now = total > kStanceMinN && s.feet[k].force > kStanceShare * total;
    if (now && !stance_[k]) {
      stance_x_[k] = s.feet[k].x, stance_y_[k] = s.feet[k].y;
      worst_[k] = 0;
    } else if (now) {
      worst_[k] = std::max(worst_[k], std::hypot(s.feet[k].x - stance_x_[k], s.feet[k].y - stance_y_[k]));
    } else if (stance_[k]) {
      ++stances_;
      slip_sum_ += worst_[k];
      slip_max_ = std::max(slip_max_, worst_[k]);
    }
    stance_[k] = now;
  }
  last_ = s;
}

WalkFigures WalkMeter::figures() const {
  WalkFigures f;
  f.commanded = commanded_;
  f.seconds = last_.t - start_.t;
  f.falls = last_.falls - start_.falls;
  f.stances = stances_;
  f.slip_mean = stances_ ? slip_sum_ / stances_ * 1000 : 0.0;
  f.slip_max = slip_max_ * 1000;
  if (f.seconds <= 0) return f;
  // Displacement in the heading frame at the window's start (m).
  const double c = std::cos(start_.torso.theta), s = std::sin(start_.torso.theta);
  const double dx = last_.torso.x - start_.torso.x, dy = last_.torso.y - start_.torso.y;
  f.forward = (c * dx + s * dy) * 1000 / f.seconds;
  f.left = (-s * dx + c * dy) * 1000 / f.seconds;
  f.turn = turned_ / f.seconds;
  if (commanded_.forward != 0) f.forward_ratio = f.forward / commanded_.forward;
  if (commanded_.left != 0) f.left_ratio = f.left / commanded_.left;
  if (commanded_.turn != 0) f.turn_ratio = f.turn / commanded_.turn;
  const double den = n_ * stt_ - st_ * st_;
  f.heading_slope = n_ < 2 || den == 0 ? 0.0 : (n_ * sty_ - st_ * sy_) / den;
  return f;
}

std::string WalkFigures::summary() const {
  auto axis = [](const char* name, double cmd, double got, double ratio, const char* unit, const char* f) {
    std::string s = std::string(name) + " " + fmt(f, cmd) + " " + unit + ": " + fmt(f, got);
    if (!std::isnan(ratio)) s += " (" + fmt("%.2f", ratio) + ")";
    return s;
  };
  std::string s = axis("forward", commanded.forward, forward, forward_ratio, "mm/s", "%.0f") + " | " +
                  axis("left", commanded.left, left, left_ratio, "mm/s", "%.0f") + " | " +
                  axis("turn", commanded.turn, turn, turn_ratio, "rad/s", "%.3f");
  s += " | heading slope " + fmt("%.1f", heading_slope * 1000) + " mrad/s";
  s += " | falls " + std::to_string(falls);
  s += " | slip mean " + fmt("%.2f", slip_mean) + " max " + fmt("%.2f", slip_max) + " mm (" +
       std::to_string(stances) + " stances)";
  s += " | over " + fmt("%.2f", seconds) + " s";
  return s;
}

// --- WalkTest -----------------------------------------------------------------

namespace {

std::string setupYaml(const WalkTestSetup& s) {
  std::ostringstream y;
  y.precision(17);
  y << "duration: 3600\nseed: " << s.seed << "\nnoise: " << (s.noise ? "on" : "off") << "\nball: none\n"
    << "robots:\n  - {team: 19, player: 1, x: " << s.x << ", y: " << s.y << ", theta: " << s.theta << "}\n";
  return y.str();
}

// The trace's short names for the FSR and gyroscope slots (the public enum's).
const char* const kFsrNames[8] = {"LFsrFrontLeft",  "LFsrFrontRight", "LFsrRearLeft",  "LFsrRearRight",
                                  "RFsrFrontLeft",  "RFsrFrontRight", "RFsrRearLeft",  "RFsrRearRight"};
const int kFsrSlots[8] = {LFsrFrontLeft, LFsrFrontRight, LFsrRearLeft, LFsrRearRight,
                          RFsrFrontLeft, RFsrFrontRight, RFsrRearLeft, RFsrRearRight};

}  // namespace

struct WalkTest::Impl {
  Impl(Simulation s, int r) : sim(std::move(s)), robot(r) {}
  Simulation sim;
  int robot;
  WalkCommand command;        // in force
  JointValues last_out{};     // the gait's command of the latest tick
  std::ofstream trace;
  std::string trace_path;

  // The robot's tick (its body's: the scenario's world), us.
  int64_t tickUs() const { return SimulationAccess::runner(sim).scenario().world.tick_us; }
  void drive(Gait gait) {
    if (!gait) throw std::invalid_argument("WalkTest: empty gait");
    sim.robot(robot).setController([this, gait = std::move(gait)](const SensorValues& s, JointValues& j) {
      command.tick = static_cast<double>(tickUs()) * 1e-6;
      gait(command, s, j);
      last_out = j;
    });
  }
  void row() {
    const SensorValues s = sim.robot(robot).sensors();
    const WalkSample w = sample();
    trace << w.t << ',' << w.torso.x << ',' << w.torso.y << ',' << w.torso.z << ',' << w.torso.theta << ','
          << command.forward << ',' << command.left << ',' << command.turn << ',' << (command.walk ? 1 : 0);
    for (int j = 0; j < kNumJoints; ++j) trace << ',' << last_out.angles[j];
    for (int j = 0; j < kNumJoints; ++j) trace << ',' << s.joints.angles[j];
    for (int k = 0; k < 8; ++k) trace << ',' << s.sensors[kFsrSlots[k]];
    trace << ',' << s.sensors[GyroscopeX] << ',' << s.sensors[GyroscopeY] << ',' << s.sensors[GyroscopeZ] << ','
          << w.falls << '\n';
  }
  WalkSample sample() const {
    if (SimulationAccess::started(sim)) return walkSample(SimulationAccess::runner(sim), robot);
    WalkSample w;  // before the first step: where the scenario puts it
    w.torso = const_cast<Simulation&>(sim).robot(robot).pose();
    return w;
  }
};

WalkTest::WalkTest(uint64_t seed, Gait gait) : WalkTest(WalkTestSetup{seed}, std::move(gait)) {}

WalkTest::WalkTest(const WalkTestSetup& setup, Gait gait)
    : WalkTest(Simulation::fromYaml(setupYaml(setup), "walk_test.yaml"), 0, std::move(gait)) {}

WalkTest::WalkTest(Simulation sim, int robot, Gait gait) {
  sim.robot(robot);  // throws std::out_of_range for a robot the scenario lacks
  impl_ = std::make_unique<Impl>(std::move(sim), robot);
  impl_->drive(std::move(gait));
}

WalkTest::WalkTest(WalkTest&&) noexcept = default;
WalkTest& WalkTest::operator=(WalkTest&&) noexcept = default;
WalkTest::~WalkTest() = default;

void WalkTest::command(const WalkCommand& c) { impl_->command = c; }
WalkCommand WalkTest::command() const { return impl_->command; }

void WalkTest::run(double seconds) {
  const int64_t n = common::nao::ticksIn(seconds, impl_->tickUs());  // the body's tick
  for (int64_t k = 0; k < n; ++k) {
    impl_->sim.step();
    if (impl_->trace.is_open()) impl_->row();
  }
}

WalkFigures WalkTest::walk(const WalkCommand& c, double settle, double window) {
  command(c);
  const int falls0 = sample().falls;
  run(settle);
  WalkMeter meter;
  meter.begin(sample(), c);
  const int64_t n = common::nao::ticksIn(window, impl_->tickUs());
  for (int64_t k = 0; k < n; ++k) {
    impl_->sim.step();
    if (impl_->trace.is_open()) impl_->row();
    meter.add(sample());
  }
  WalkFigures f = meter.figures();
  f.falls = sample().falls - falls0;
  return f;
}

void WalkTest::trace(const std::string& csv_path) {
  stopTrace();
  impl_->trace.open(csv_path, std::ios::trunc);
  if (!impl_->trace) throw std::runtime_error(csv_path + ": cannot write the trace");
  impl_->trace_path = csv_path;
  impl_->trace.precision(7);
  std::ofstream& o = impl_->trace;
  o << "# simswift walk trace: one row per tick of the robot's body (10 ms on a V5, 12 ms on a V6), after the\n"
       "#   tick's physics and the gait's answer.\n"
       "# t: s of simulated time. x, y, z (m), theta (rad): the TRUE torso pose, field frame (origin the centre\n"
       "#   spot, x toward the red goal, z up; theta the heading of the torso's x axis).\n"
       "# cmd_forward, cmd_left (mm/s), cmd_turn (rad/s), cmd_walk (1 walk, 0 stand): the walk command in force.\n"
       "# cmd_<joint> (rad): the angles the gait commanded this tick (libagent JointValues.angles; they act\n"
       "#   during the next tick). meas_<joint> (rad): the measured angles the gait read (sensors.joints.angles).\n"
       "# <foot>Fsr<corner> (kg): the eight FSR slots as the program read them.\n"
       "# GyroscopeX, GyroscopeY, GyroscopeZ: the libagent slots exactly as the program read them this tick, not\n"
       "#   converted by the kit: rad/s about the torso's x (forward), y (left), z (up) axes with the signs the\n"
       "#   simulator's sensor block gives for the NAO V5 (each slot's sign and source: docs/libagent.md).\n"
       "# falls: the simulator's fall count so far (torso origin below 0.20 m).\n";
  o << "t,x,y,z,theta,cmd_forward,cmd_left,cmd_turn,cmd_walk";
  for (int j = 0; j < kNumJoints; ++j) o << ",cmd_" << common::libagent::Joints::kNames[j];
  for (int j = 0; j < kNumJoints; ++j) o << ",meas_" << common::libagent::Joints::kNames[j];
  for (const char* f : kFsrNames) o << ',' << f;
  o << ",GyroscopeX,GyroscopeY,GyroscopeZ,falls\n";
}

void WalkTest::stopTrace() {
  if (!impl_->trace.is_open()) return;
  impl_->trace.close();
  if (impl_->trace.fail()) throw std::runtime_error(impl_->trace_path + ": writing the trace failed");
}

WalkSample WalkTest::sample() const { return impl_->sample(); }
Simulation& WalkTest::simulation() { return impl_->sim; }
Robot WalkTest::robot() { return impl_->sim.robot(impl_->robot); }

// --- plot ---------------------------------------------------------------------

bool plotTrace(const std::string& csv_path, const std::string& png_path, std::string* message) {
  std::string sink;
  std::string& msg = message ? *message : sink;
  std::ifstream in(csv_path);
  if (!in) {
    msg = csv_path + ": cannot read the trace";
    return false;
  }
  std::string header;
  while (std::getline(in, header) && (header.empty() || header[0] == '#')) {
  }
  std::vector<std::string> names;
  {
    std::stringstream h(header);
    for (std::string n; std::getline(h, n, ',');) names.push_back(n);
  }
  auto col = [&](const std::string& n) -> int {
    const auto it = std::find(names.begin(), names.end(), n);
    if (it == names.end()) throw std::runtime_error(csv_path + ": not a walk trace (no column '" + n + "')");
    return static_cast<int>(it - names.begin()) + 1;  // gnuplot counts from 1
  };
  // gnuplot runs in the PNG's folder on absolute or relative names as given.
  const std::string::size_type slash = png_path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : png_path.substr(0, slash);
  std::string stem = slash == std::string::npos ? png_path : png_path.substr(slash + 1);
  if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".png") == 0) stem.resize(stem.size() - 4);
  std::string csv_abs = csv_path;
  if (csv_abs.empty() || csv_abs[0] != '/') {
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) {
      msg = "plotTrace: cannot read the working folder";
      return false;
    }
    csv_abs = std::string(cwd) + "/" + csv_path;
  }
  std::ofstream gp(dir + "/" + stem + ".gp", std::ios::trunc);
  if (!gp) {
    msg = dir + "/" + stem + ".gp: cannot write the plot script";
    return false;
  }
  try {
    auto u = [&](const std::string& n) { return std::to_string(col(n)); };
    auto pair = [&](const std::string& joint, const char* colour) {
      return "'" + csv_abs + "' every ::1 using " + u("t") + ":" + u("cmd_" + joint) + " with lines dt 2 lc rgb '" +
             colour + "' title '" + joint + " cmd', '' every ::1 using " + u("t") + ":" + u("meas_" + joint) +
             " with lines lc rgb '" + colour + "' title 'measured'";
    };
    auto sum = [&](const char* foot) {
      std::string s;
      for (const char* c : {"FrontLeft", "FrontRight", "RearLeft", "RearRight"})
        s += (s.empty() ? "$" : "+$") + u(std::string(foot) + "Fsr" + c);
      return "(" + s + ")";
    };
    gp << "set datafile separator ','\nset datafile commentschars '#'\n"
       << "set terminal pngcairo size 1000,1500 font ',9'\nset output '" << stem << ".png'\n"
       << "set termoption noenhanced\nset multiplot layout 6,1 title '" << csv_path << "'\n"
       << "set grid\nset key outside right\nset lmargin 10\nset rmargin 24\n"
       << "set ylabel 'x (m)'\nset y2label 'y (m)'\nset y2tics\nplot '" << csv_abs << "' every ::1 using "
       << u("t") << ":" << u("x") << " with lines title 'x', '' every ::1 using " << u("t") << ":" << u("y")
       << " axes x1y2 with lines title 'y (right axis)'\nunset y2tics\nunset y2label\n"
       << "set ylabel 'rad'\nplot '" << csv_abs << "' every ::1 using " << u("t") << ":" << u("theta")
       << " with lines title 'heading'\n"
       << "plot " << pair("LHipPitch", "red") << ", " << pair("LKneePitch", "blue") << ", "
       << pair("LAnklePitch", "dark-green") << "\n"
       << "plot " << pair("RHipPitch", "red") << ", " << pair("RKneePitch", "blue") << ", "
       << pair("RAnklePitch", "dark-green") << "\n"
       << "set ylabel 'kg'\nplot '" << csv_abs << "' every ::1 using " << u("t") << ":" << sum("L")
       << " with lines title 'left FSRs', '' every ::1 using " << u("t") << ":" << sum("R")
       << " with lines title 'right FSRs'\n"
       << "set ylabel 'gyroscope slot'\nset xlabel 's'\nplot '" << csv_abs << "' every ::1 using " << u("t") << ":"
       << u("GyroscopeX") << " with lines title 'GyroscopeX', '' every ::1 using " << u("t") << ":"
       << u("GyroscopeY") << " with lines title 'GyroscopeY', '' every ::1 using " << u("t") << ":"
       << u("GyroscopeZ") << " with lines title 'GyroscopeZ'\n"
       << "unset multiplot\n";
  } catch (const std::runtime_error& e) {
    msg = e.what();
    return false;
  }
  gp.close();
  if (experiment::runGnuplot(dir, stem, "the trace plot", &msg)) return true;
  if (msg.rfind("gnuplot not found", 0) == 0)
    msg = "gnuplot not found: the trace plot skipped (install gnuplot-nox; the script is " + dir + "/" + stem + ".gp)";
  return false;
}

// --- the reference walk ------------------------------------------------------

Gait referenceGait() {
  programs::ReferenceWalkStep walk = programs::referenceWalk();
  return [walk](const WalkCommand& c, const SensorValues& s, JointValues& j) {
    common::libagent::SensorValues in;
    common::libagent::JointValues out;
    std::memcpy(&in, &s, sizeof in);
    std::memcpy(&out, &j, sizeof out);
    walk(c.walk, c.forward, c.left, c.turn, c.tick, in, out);  // the kit's tick: the robot's body's
    std::memcpy(&j, &out, sizeof j);
  };
}

}  // namespace simswift::api
