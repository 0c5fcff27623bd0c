// A scenario's physics: block is the World's own WorldConfig, read field by
// field: each key reaches its field, the defaults are WorldConfig's, and a
// value out of range is refused at read time naming file, line and key, by
// the same rule (checkWorldConfig) World's constructor applies.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/runner/Scenario.hpp"
#include "tests/runner/RunnerTestUtil.hpp"
#include "sim/world/World.hpp"

using simswift::ConfigError;
using simswift::WorldConfig;
using simswift::runner::Scenario;

namespace {

using runnertest::kOneRobot;

// The physics block on line 2 (each key on its own line below it).
Scenario withPhysics(const std::string& keys) {
  return Scenario::parse("duration: 1\nphysics:\n" + keys + kOneRobot, "p.yaml");
}

}  // namespace

TEST(ScenarioPhysics, DefaultsAreWorldConfigsAndEveryKeyReachesItsField) {
  const WorldConfig d;
  const WorldConfig none = Scenario::parse(kOneRobot, "p.yaml").world;
  EXPECT_EQ(none.solver, d.solver);
  EXPECT_EQ(none.substeps, d.substeps);
  EXPECT_EQ(none.quick_iterations, d.quick_iterations);
  EXPECT_EQ(none.sole_stiffness, d.sole_stiffness);
  EXPECT_EQ(none.tick_us, d.tick_us);
  const WorldConfig w = withPhysics(
                            "  solver: exact\n  substeps: 3\n  iterations: 30\n  quick_w: 1.3\n  erp: 0.5\n"
                            "  cfm: 1.0e-6\n  joint_projection_sweeps: 4\n  joint_projection_tolerance: 2.0e-4\n"
                            "  sole_nx: 2\n  sole_ny: 2\n  sole_stiffness: 1.0e5\n  sole_damping: 1.0e3\n"
                            "  sole_anchor_erp: 0.1\n  sole_anchor_slip: 0.01\n")
                            .world;
  EXPECT_EQ(w.solver, WorldConfig::Solver::Exact);
  EXPECT_EQ(w.substeps, 3);
  EXPECT_EQ(w.quick_iterations, 30);
  EXPECT_EQ(w.quick_w, 1.3);
  EXPECT_EQ(w.erp, 0.5);
  EXPECT_EQ(w.cfm, 1.0e-6);
  EXPECT_EQ(w.joint_projection_sweeps, 4);
  EXPECT_EQ(w.joint_projection_tolerance, 2.0e-4);
  EXPECT_EQ(w.sole_nx, 2);
  EXPECT_EQ(w.sole_ny, 2);
  EXPECT_EQ(w.sole_stiffness, 1.0e5);
  EXPECT_EQ(w.sole_damping, 1.0e3);
  EXPECT_EQ(w.sole_anchor_erp, 0.1);
  EXPECT_EQ(w.sole_anchor_slip, 0.01);
  // Unset: as before.
  EXPECT_EQ(w.gravity, d.gravity);
  EXPECT_EQ(w.max_distance, d.max_distance);
}

// Each exposed key with a value its rule refuses, on line 4 (one good key
// on line 3 first, so the line is the bad value's own, not the block's).
TEST(ScenarioPhysics, ABadValueIsRefusedAtReadTimeWithFileLineAndKey) {
  struct Bad {
    std::string key, value, why;
  };
  const std::vector<Bad> bad = {
      {"solver", "fast", "expected one of quick, exact (got 'fast')"},
      {"substeps", "-1", "must be in [0, 100] (got -1)"},
      {"substeps", "2.5", "expected an integer"},
      {"iterations", "1001", "must be in [1, 1000] (got 1001)"},
      {"quick_w", "2", "must be in (0, 2) (got 2)"},
      {"erp", "1.5", "must be in [0, 1] (got 1.5)"},
      {"cfm", "-1e-5", "must be in [0, 1] (got -1e-05)"},
      {"joint_projection_sweeps", "-1", "must be in [0, 1000] (got -1)"},
      {"joint_projection_tolerance", "0", "must be > 0 (got 0)"},
      {"sole_nx", "0", "must be in [1, 64] (got 0)"},
      {"sole_ny", "100", "must be in [1, 64] (got 100)"},
      {"sole_ny", "30", "sole_nx x sole_ny must be at most 64 points (got 4 x 30)"},
      {"sole_stiffness", "0", "must be > 0 (got 0)"},
      {"sole_damping", "-1", "must be >= 0 (got -1)"},
      {"sole_anchor_erp", "2", "must be in [0, 1] (got 2)"},
      {"sole_anchor_slip", "0", "must be > 0 (got 0)"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.key + ": " + b.value);
    const std::string good = b.key == "substeps" ? "  erp: 0.8\n" : "  substeps: 2\n";
    try {
      withPhysics(good + "  " + b.key + ": " + b.value + "\n");
      ADD_FAILURE() << "accepted";
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.file, "p.yaml");
      EXPECT_EQ(e.line, 4) << e.what();
      EXPECT_EQ(e.key, "physics." + b.key) << e.what();
      EXPECT_NE(std::string(e.what()).find("p.yaml:4: physics." + b.key + ": " + b.why), std::string::npos)
          << e.what();
    }
  }
}

// World's constructor applies the same rule to a config built in code,
// naming the field (no file to name).
TEST(ScenarioPhysics, TheWorldRefusesWhatTheReaderRefuses) {
  WorldConfig c;
  c.erp = 1.5;
  ASSERT_TRUE(simswift::checkWorldConfig(c));
  EXPECT_EQ(simswift::checkWorldConfig(c)->field, "erp");
  try {
    simswift::World w(simswift::FieldConfig::spl2017(), c);
    ADD_FAILURE() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "world: erp: must be in [0, 1] (got 1.5)");
  }
  EXPECT_FALSE(simswift::checkWorldConfig(WorldConfig{}));  // the defaults pass
}
