// Field files: every dimension in a sane range, the goal checked as a whole
// (a post shorter than its diameter crashed ODE's capsule code before these
// checks), errors naming file, line and key.
#include <gtest/gtest.h>

#include <filesystem>

#include "sim/world/FieldConfig.hpp"
#include "sim/world/World.hpp"
#include "tests/support/ConfigErrors.hpp"

using simswift::ConfigError;
using simswift::FieldConfig;

namespace {

std::string fieldError(const std::string& yaml) {
  return simswift::testing::configError([&] { FieldConfig::parseYaml(yaml, "f.yaml"); });
}

}  // namespace

TEST(FieldHardening, ShortPostIsRefusedWithItsLine) {
  const std::string err = fieldError("field:\n  goal:\n    post_diameter: 0.1\n    post_height: 0.04\n");
  EXPECT_EQ(err.rfind("f.yaml:4: field.goal.post_height:", 0), 0u) << err;
  EXPECT_NE(err.find("post_diameter"), std::string::npos) << err;
}

TEST(FieldHardening, AbsurdDimensionsAreRefused) {
  struct Case {
    const char* yaml;
    const char* prefix;
  } cases[] = {
      {"field:\n  length: 1e12\n", "f.yaml:2: field.length:"},
      {"field:\n  width: 0.001\n", "f.yaml:2: field.width:"},
      {"field:\n  border: 1e300\n", "f.yaml:2: field.border:"},
      {"field:\n  ball:\n    mass: 1e-300\n", "f.yaml:3: field.ball.mass:"},
      {"field:\n  ball:\n    diameter: 50\n", "f.yaml:3: field.ball.diameter:"},
      {"field:\n  goal:\n    inner_width: 7\n", "f.yaml:3: field.goal.inner_width:"},
      {"field:\n  goal:\n    net_height: 2\n", "f.yaml:3: field.goal.net_height:"},
      {"field:\n  goal:\n    net_stiffness: 1e200\n", "f.yaml:3: field.goal.net_stiffness:"},
      {"field:\n  surface:\n    soft_cfm: 1e10\n", "f.yaml:3: field.surface.soft_cfm:"},
      {"field:\n  surface:\n    friction: .inf\n", "f.yaml:3: field.surface.friction:"},
      {"field:\n  circles:\n    - {centre: [0, 0], radius: 1e9}\n", "f.yaml:3: field.circles[0].radius:"},
  };
  for (const Case& c : cases) {
    const std::string err = fieldError(c.yaml);
    EXPECT_EQ(err.rfind(c.prefix, 0), 0u) << c.yaml << " -> " << err;
  }
}

TEST(FieldHardening, ShippedFieldStillLoadsAndBuilds) {
  const FieldConfig f = FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");
  simswift::World w(f);
  w.step();
  EXPECT_TRUE(w.takeEvents().empty());
}

TEST(FieldHardening, DirectoryIsNotAFieldFile) {
  try {
    FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("fields:1: is a directory"), std::string::npos) << e.what();
  }
}

// A misspelt key is named at its own line with the key it resembles (issue
// 34 item 5): the required field: map (it was "missing" at the document's
// first line), an optional key, and a line's required from: in a list.
TEST(FieldHardening, MisspeltKeysAreNamedAtTheirLineWithTheNearestKey) {
  EXPECT_EQ(fieldError("# a field\nfeild:\n  length: 9.0\n"),
            "f.yaml:2: unknown key 'feild' in <document> (did you mean field? a required key, missing)");
  const std::string opt = fieldError("field:\n  length: 9.0\n  widht: 6.0\n");
  EXPECT_EQ(opt.rfind("f.yaml:3: unknown key 'widht' in field (did you mean width?); expected one of ", 0), 0u) << opt;
  EXPECT_EQ(fieldError("field:\n  lines:\n    - {name: b, From: [0, 0], to: [0, 1]}\n"),
            "f.yaml:3: unknown key 'From' in field.lines[0] (did you mean from? a required key, missing)");
}
