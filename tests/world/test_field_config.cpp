// Field YAML loading and its error messages.
#include <gtest/gtest.h>

#include "sim/world/FieldConfig.hpp"
#include "sim/world/ConfigError.hpp"
#include "tests/support/ConfigErrors.hpp"

using namespace simswift;

namespace {

// Returns the ConfigError message parseYaml throws (fails the test if none).
std::string errorOf(const std::string& yaml) {
  const std::string e = simswift::testing::configError([&] { FieldConfig::parseYaml(yaml, "test.yaml"); });
  if (e.empty()) ADD_FAILURE() << "no ConfigError for:\n" << yaml;
  return e;
}

}  // namespace

TEST(FieldConfig, SplFileLoadsWithRuleDimensions) {
  FieldConfig f = FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");
  EXPECT_DOUBLE_EQ(f.length, 9.0);
  EXPECT_DOUBLE_EQ(f.width, 6.0);
  EXPECT_DOUBLE_EQ(f.border, 0.7);
  EXPECT_NEAR(f.carpetLength(), 10.4, 1e-12);
  EXPECT_NEAR(f.carpetWidth(), 7.4, 1e-12);
  // 2 touch + 2 goal + halfway + 2 x 3 penalty-area lines.
  ASSERT_EQ(f.lines.size(), 11u);
  for (const auto& l : f.lines) EXPECT_DOUBLE_EQ(l.width, 0.05);
  ASSERT_EQ(f.circles.size(), 1u);
  EXPECT_DOUBLE_EQ(f.circles[0].radius, 0.75);
  ASSERT_EQ(f.crosses.size(), 3u);
  EXPECT_DOUBLE_EQ(f.crosses[0].x, -3.2);  // 1.3 m from the goal line
  EXPECT_DOUBLE_EQ(f.crosses[2].x, 3.2);
  EXPECT_DOUBLE_EQ(f.goal.post_diameter, 0.1);
  EXPECT_DOUBLE_EQ(f.goal.inner_width + f.goal.post_diameter, 1.6);  // post centres
  EXPECT_DOUBLE_EQ(f.goal.depth, 0.5);
  EXPECT_DOUBLE_EQ(f.ball.diameter, 0.1);
  EXPECT_DOUBLE_EQ(f.ball.mass, 0.044);
  EXPECT_NE(f.source.find("spl_2017.yaml"), std::string::npos);
}

TEST(FieldConfig, FileMatchesGeneratedSplMarkings) {
  FieldConfig file = FieldConfig::loadYaml(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");
  FieldConfig gen = FieldConfig::spl2017();
  ASSERT_EQ(file.lines.size(), gen.lines.size());
  for (size_t i = 0; i < gen.lines.size(); ++i) {
    EXPECT_DOUBLE_EQ(file.lines[i].ax, gen.lines[i].ax) << i;
    EXPECT_DOUBLE_EQ(file.lines[i].ay, gen.lines[i].ay) << i;
    EXPECT_DOUBLE_EQ(file.lines[i].bx, gen.lines[i].bx) << i;
    EXPECT_DOUBLE_EQ(file.lines[i].by, gen.lines[i].by) << i;
  }
}

TEST(FieldConfig, MinimalYamlGivesSplDefaults) {
  FieldConfig f = FieldConfig::parseYaml("field: {}\n", "min.yaml");
  EXPECT_EQ(f.lines.size(), 11u);
  EXPECT_EQ(f.crosses.size(), 3u);
  EXPECT_DOUBLE_EQ(f.ball.mass, 0.044);
}

TEST(FieldConfig, UnknownKeyNamesKeyLineAndChoices) {
  std::string msg = errorOf("field:\n  length: 9\n  bal:\n    mass: 0.04\n");
  EXPECT_NE(msg.find("test.yaml:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'bal' in field"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ball"), std::string::npos) << msg;  // listed as expected
}

TEST(FieldConfig, MissingRequiredFieldIsAnError) {
  std::string msg = errorOf("field:\n  lines:\n    - {from: [0, 0]}\n");
  EXPECT_NE(msg.find("field.lines[0].to"), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing"), std::string::npos) << msg;
  EXPECT_NE(msg.find("test.yaml:3"), std::string::npos) << msg;

  std::string top = errorOf("ball: {}\n");
  EXPECT_NE(top.find("field"), std::string::npos) << top;
}

TEST(FieldConfig, BadValueNamesKeyLineAndValue) {
  std::string msg = errorOf("field:\n  ball:\n    diameter: 0.1\n    mass: -1\n");
  EXPECT_NE(msg.find("test.yaml:4: field.ball.mass: must be in [0.001, 10] (got -1)"), std::string::npos)
      << msg;
}

TEST(FieldConfig, WrongTypeIsAnError) {
  std::string msg = errorOf("field:\n  width: wide\n");
  EXPECT_NE(msg.find("test.yaml:2: field.width: expected a number (got 'wide')"),
            std::string::npos)
      << msg;
  std::string list = errorOf("field:\n  crosses:\n    - {at: [1, 2, 3]}\n");
  EXPECT_NE(list.find("field.crosses[0].at"), std::string::npos) << list;
}

TEST(FieldConfig, SyntaxErrorNamesLine) {
  std::string msg = errorOf("field:\n  length: [9\n  width: 6\n");
  EXPECT_NE(msg.find("test.yaml:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("syntax"), std::string::npos) << msg;
}

TEST(FieldConfig, MissingFileIsAnError) {
  EXPECT_THROW(FieldConfig::loadYaml("/nonexistent/field.yaml"), ConfigError);
}

TEST(YamlReader, IntegersBoolsChoicesAndBounds) {
  YAML::Node n = YamlReader::parse("a: 3\nb: 2.5\nc: yes\nd: quick\ne: 7\n", "r.yaml");
  YamlReader r(n, "r.yaml", "sim");
  EXPECT_EQ(r.integer("a", Range::closed(1, 5)), 3);
  EXPECT_THROW(r.integer("b"), ConfigError);  // not an integer
  EXPECT_TRUE(r.boolean("c"));
  EXPECT_EQ(r.choice("d", "exact", {"exact", "quick"}), "quick");
  try {
    r.integer("e", Range::closed(1, 5));
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("r.yaml:5: sim.e: must be in [1, 5] (got 7)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(r.integer("absent", 4), 4);
  EXPECT_NO_THROW(r.finish());  // every key was asked for
}
