// ConfigError keeps the file, the line and the key its throw site gave
// (issue 32): the public API hands them on as they are, nothing reads them
// back out of the message, whose text stays "file:line: key: what".
#include <gtest/gtest.h>

#include <string>

#include "common/config/YamlReader.hpp"

using common::config::ConfigError;
using common::config::Range;
using common::config::YamlReader;

namespace {

// The error reading `text` as {robots: [{team: <number in [0, 99]>}]} throws.
ConfigError teamListError(const std::string& text, const std::string& file) {
  try {
    const YAML::Node root = YamlReader::parse(text, file);
    YamlReader top(root, file);
    for (YamlReader robot : top.list("robots")) {
      robot.number("team", Range::closed(0, 99));
      robot.finish();
    }
    top.finish();
  } catch (const ConfigError& e) {
    return e;
  }
  return ConfigError("no error");
}

}  // namespace

TEST(ConfigErrorFields, TheMessageIsComposedFromTheParts) {
  const ConfigError keyed("f.yaml", 12, "field.ball.mass", "must be > 0 (got -1)");
  EXPECT_STREQ(keyed.what(), "f.yaml:12: field.ball.mass: must be > 0 (got -1)");
  EXPECT_EQ(keyed.file, "f.yaml");
  EXPECT_EQ(keyed.line, 12);
  EXPECT_EQ(keyed.key, "field.ball.mass");
  const ConfigError unkeyed("f.yaml", 1, "", "cannot open file");
  EXPECT_STREQ(unkeyed.what(), "f.yaml:1: cannot open file");
  const ConfigError nowhere("world: substeps must be >= 1");
  EXPECT_EQ(nowhere.file, "");
  EXPECT_EQ(nowhere.line, 0);
  EXPECT_EQ(nowhere.key, "");
}

TEST(ConfigErrorFields, AValueOutOfRangeNamesItsFileLineAndKeyPath) {
  const ConfigError e = teamListError("robots:\n  - {team: 5}\n  - {team: 300}\n", "teams.yaml");
  EXPECT_EQ(e.file, "teams.yaml");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.key, "robots[1].team");
  EXPECT_EQ(std::string(e.what()).rfind("teams.yaml:3: robots[1].team: must be in [0, 99]", 0), 0u) << e.what();
}

// A file name with ": 9: " in it is the file's, all of it (a reading of the
// text would stop at the first such colon).
TEST(ConfigErrorFields, AFileNameWithColonsAndDigitsIsKeptWhole) {
  const ConfigError e = teamListError("robots:\n  - {team: -1}\n", "runs:9: a: b.yaml");
  EXPECT_EQ(e.file, "runs:9: a: b.yaml");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.key, "robots[0].team");
}

// Errors of the text itself name no key, even when their message has a
// colon of its own ("YAML syntax error: ...") or names the document.
TEST(ConfigErrorFields, SyntaxAndDocumentErrorsHaveALineAndNoKey) {
  const ConfigError syntax = teamListError("robots:\n  - {team: 5\n", "syntax.yaml");
  EXPECT_EQ(syntax.file, "syntax.yaml");
  EXPECT_EQ(syntax.line, 3);  // yaml-cpp's mark: the end, where the flow map is still open
  EXPECT_EQ(syntax.key, "");
  EXPECT_NE(std::string(syntax.what()).find(": YAML syntax error: "), std::string::npos) << syntax.what();
  const ConfigError list = teamListError("- 1\n- 2\n", "list.yaml");
  EXPECT_EQ(list.file, "list.yaml");
  EXPECT_EQ(list.line, 1);
  EXPECT_EQ(list.key, "");
  EXPECT_EQ(std::string(list.what()).rfind("list.yaml:1: <document>: ", 0), 0u) << list.what();
}

TEST(ConfigErrorFields, AMissingFileIsItsPathAtLineOne) {
  try {
    YamlReader::parseFile("/no/such/config.yaml");
    FAIL() << "read";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file, "/no/such/config.yaml");
    EXPECT_EQ(e.line, 1);
    EXPECT_EQ(e.key, "");
    EXPECT_STREQ(e.what(), "/no/such/config.yaml:1: cannot open file");
  }
}
