// Determinism of the physics alone, pinned: a NAO standing on the carpet
// with fixed servo targets (the robot program's standing posture,
// stiffness 1) and no robot program, kTicks ticks of the production World,
// ends with kPinnedPhysicsHash. Beside tests/runner/test_determinism.cpp
// (the whole loop with robot code), this isolates the physics: contacts,
// servos, solver, joint projection. The same hash whether the World runs
// alone or beside other Worlds stepping on other threads (ODE's random
// generator, which QuickStep's row shuffle draws from, is process-wide).
//
// Re-pin only when the physics changes on purpose (World, Contacts,
// RobotBody, Servo, JointProjector, WorldConfig defaults, ODE itself, the
// URDF): run
//   build/tests/test_world --gtest_filter='PhysicsHash.*'
// paste the value the failure prints, and say in the commit why physics
// changed. A change anywhere else (robot code, sensors, the runner) must
// leave it as it is.
#include <gtest/gtest.h>

#include <memory>
#include <thread>
#include <vector>

#include "agent/program/Postures.hpp"
#include "sim/nao_model/NaoBinding.hpp"
#include "sim/world/World.hpp"
#include "tests/support/HashText.hpp"

using simswift::testing::hashLiteral;

using namespace simswift;

namespace {

constexpr uint64_t kPinnedPhysicsHash = 0x8785061b30585b2cull;  // since: the physics-only hash was added
constexpr int kTicks = 300;                      // 3 s

std::shared_ptr<const RobotModel> nao() {
  static const auto m = std::make_shared<const RobotModel>(RobotModel::loadUrdf(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf"));
  return m;
}

// One NAO standing at (-1, 0.5) m facing 0.3 rad, the ball resting 0.3 m in
// front of it; stand targets latched once.
uint64_t physicsHash() {
  World w(FieldConfig::spl2017());
  w.placeBall(-0.6, 0.6);
  const NaoBinding binding(*nao());
  const auto stand = agent::program::postureAngles(agent::program::Posture::Stand);
  const int i = w.addRobot(nao(), -1.0, 0.5, 0.3, binding.posture(stand));
  NaoBinding::SlotArray stiffness;
  stiffness.fill(1.0f);
  binding.command(w.robot(i), stand, stiffness);
  for (int k = 0; k < kTicks; ++k) w.step();
  return w.stateHash();
}

}  // namespace

TEST(PhysicsHash, StandingNaoPinned) {
  const uint64_t h = physicsHash();
  EXPECT_EQ(h, kPinnedPhysicsHash) << "physics hash is " << hashLiteral(h) << ", pinned " << hashLiteral(kPinnedPhysicsHash)
                                   << ": if physics changed on purpose, re-pin in " << __FILE__;
}

// 1, 2 and 4 Worlds stepping at once on their own threads: each ends with
// the pinned hash.
TEST(PhysicsHash, SameOnAnyNumberOfThreads) {
  for (int threads : {1, 2, 4}) {
    std::vector<uint64_t> hashes(threads, 0);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back([&hashes, t] { hashes[t] = physicsHash(); });
    for (auto& th : pool) th.join();
    for (int t = 0; t < threads; ++t)
      EXPECT_EQ(hashes[t], kPinnedPhysicsHash) << threads << " threads, thread " << t << ": " << hashLiteral(hashes[t]);
  }
}
