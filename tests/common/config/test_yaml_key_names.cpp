// Keys that are not names (common/config/YamlReader.hpp, issue 45 item 6): a
// list, a map or null as a key is refused at its own line with the map's
// key path, by the first getter of that map -- never yaml-cpp's unplaced
// "bad conversion" -- and keys() lists a map's keys with their lines.
#include <gtest/gtest.h>

#include <string>

#include "common/config/YamlReader.hpp"
#include "tests/support/ConfigErrors.hpp"

using common::config::YamlReader;

namespace {

std::string nestedKeyError(const std::string& text) {
  return simswift::testing::configError([&] {
    const YAML::Node root = YamlReader::parse(text, "k.yaml");
    YamlReader top(root, "k.yaml");
    YamlReader m = top.map("m");
    (void)m.number("a", 0.0);
    m.finish();
    top.finish();
  });
}

}  // namespace

TEST(YamlKeyNames, AListMapOrNullKeyIsRefusedAtItsLine) {
  EXPECT_EQ(nestedKeyError("m:\n  a: 1\n  ? [b]\n  : 2\n"), "k.yaml:3: m: a key must be a name, not a list (got [b])");
  EXPECT_EQ(nestedKeyError("m: {a: 1, ? {b: c}: 2}\n"), "k.yaml:1: m: a key must be a name, not a map (got {b: c})");
  EXPECT_EQ(nestedKeyError("m:\n  a: 1\n  ~: 2\n"), "k.yaml:3: m: a key must be a name, not null (got ~)");
  // At the document's top level.
  EXPECT_EQ(nestedKeyError("m: {a: 1}\n? [x]\n: 1\n"), "k.yaml:2: <document>: a key must be a name, not a list (got [x])");
  EXPECT_EQ(nestedKeyError("m: {a: 1}\n"), "");
}

TEST(YamlKeyNames, KeysListsTheMapsKeysWithTheirLines) {
  const YAML::Node root = YamlReader::parse("A: 1\nB:\n  c: 2\n", "k.yaml");
  const std::vector<YamlReader::Key> keys = YamlReader(root, "k.yaml").keys();
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].name, "A");
  EXPECT_EQ(keys[0].line, 1);
  EXPECT_EQ(keys[1].name, "B");
  EXPECT_EQ(keys[1].line, 2);
}
