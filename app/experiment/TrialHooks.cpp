#include "app/experiment/TrialHooks.hpp"

#include <cmath>

#include "sim/vision/VisionOracle.hpp"

namespace simswift::experiment {

double VisionFoundRule::ballDistance(runner::Runner& r, int robot) {
  const vision::GroundFrame g = r.visionOracle().groundFrame(r.world(), robot);
  const Eigen::Vector3d ball = r.world().ballPosition();
  return std::hypot(ball.x() - g.origin.x(), ball.y() - g.origin.y());
}

int VisionFoundRule::finder(const Experiment& e, runner::Runner& r) const {
  for (int i = 0; i < r.numRobots(); ++i) {
    const vision::VisionOracle::BallSighting s = r.visionOracle().ballSighting(i);
    const double true_distance = e.found.sees ? 0.0 : ballDistance(r, i);
    if (foundBy(e.found, s.frame, s.distance_mm * 1e-3, s.consecutive, r.lastFrame(), true_distance)) return i;
  }
  return -1;
}

void checkBehaviours(const Experiment& e, const TrialHooks& hooks) {
  auto check = [&](const Experiment& x) {
    for (const Setup& s : x.setups)
      for (const ExperimentRobot& r : s.robots) hooks.behaviours->check(x, r);
  };
  check(e);
  if (!e.swept()) return;
  // Swept behaviour overrides are validated by the behaviour's reader here:
  // each value alone (an error names its line), then every cell.
  for (const SweepAxis& a : e.sweep)
    for (size_t v = 0; v < a.values.size(); ++v) {
      try {
        if (a.values[v].alone) check(*a.values[v].alone);
      } catch (const ConfigError& err) {
        throw blameValue(e.source, a, static_cast<int>(v), err.what());
      }
    }
  for (int c = 0; c < e.numCells(); ++c) {
    try {
      check(e.cell(c));
    } catch (const ConfigError& err) {
      throw blameCell(e.source, e.sweep_line, e.sweep, c, err.what());
    }
  }
}

}  // namespace simswift::experiment
