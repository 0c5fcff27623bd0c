// Real-time factor of N standing robots, physics and sensors only (no robot
// code): World::step() plus every robot's SensorSuite::update() per 10 ms
// tick, on one core. The targets are >= 30x / 10x / 3x for 1 / 3 / 10
// robots (aim 100x / 30x / 10x).
//
// Usage: bench_world [SIM_SECONDS=20] ; figures are printed and appended to
// the results file (see bench/BenchResults.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "BenchResults.hpp"
#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/sensors/SensorSuite.hpp"
#include "sim/world/World.hpp"

using namespace simswift;
namespace ap = agent::program;

int main(int argc, char** argv) {
  const double sim_seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  auto model = std::make_shared<const RobotModel>(
      RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  const FieldConfig field = FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");

  // The robot program's standing posture (agent/program/Postures.hpp), stiffness 1.
  const ap::JointArray stand = ap::postureAngles(ap::Posture::Stand);
  ap::JointArray stiff;
  stiff.fill(ap::postureStiffness(ap::Posture::Stand));
  const simswift::NaoBinding nao(*model);
  const std::vector<double> posture = nao.posture(stand);

  std::printf("simswift world benchmark: %.0f simulated s per case, physics + sensors, one core\n",
              sim_seconds);
  for (int n : {1, 3, 10}) {
    World world(field);
    std::vector<std::unique_ptr<sensors::SensorSuite>> suites;
    for (int r = 0; r < n; ++r) {
      // Robots 1 m apart along the half-way line, facing +x.
      const int id = world.addRobot(model, -2.0 + (r % 5) * 1.0, (r < 5 ? 1.5 : -1.5), 0.0, posture);
      nao.command(world.robot(id), stand, stiff);
    }
    sensors::SensorConfig cfg;
    for (int r = 0; r < n; ++r) suites.push_back(std::make_unique<sensors::SensorSuite>(world, r, cfg));

    const long ticks = std::lround(sim_seconds / kTickSeconds);
    const auto t0 = std::chrono::steady_clock::now();
    for (long t = 0; t < ticks; ++t) {
      world.step();
      for (auto& s : suites) s->update(world);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char name[64];
    std::snprintf(name, sizeof name, "world.standing_%d_robot%s.realtime_factor", n, n > 1 ? "s" : "");
    bench::report(name, sim_seconds / wall, "x");
  }
  return 0;
}
