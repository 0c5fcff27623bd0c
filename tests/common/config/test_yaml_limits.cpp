// The configuration reader's limits (common/config/YamlReader.hpp): input
// no YAML file needs is refused with the file, a line and the limit named,
// before the readers walk it; ordinary files, aliases included, still load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/config/YamlReader.hpp"
#include "tests/support/ConfigErrors.hpp"

using common::config::expandedNodes;
using common::config::kMaxConfigBytes;
using common::config::kMaxConfigNodes;
using common::config::YamlReader;

namespace {

std::string errorOf(const std::string& text) {
  return simswift::testing::configError([&] { YamlReader::parse(text, "f.yaml"); });
}

}  // namespace

TEST(YamlLimits, NulByteIsRefusedAtItsLine) {
  std::string text = "a: 1\nb: 2\n# a comment with ";
  text += '\0';
  text += " in it\nc: 3\n";
  const std::string msg = errorOf(text);
  EXPECT_EQ(msg.rfind("f.yaml:3: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("NUL byte"), std::string::npos) << msg;
}

TEST(YamlLimits, TooDeepNestingSaysSo) {
  // yaml-cpp's own guard says "bad file"; the message names the nesting.
  const std::string msg = errorOf("a: 1\nb: " + std::string(600, '[') + std::string(600, ']') + "\n");
  EXPECT_EQ(msg.rfind("f.yaml:2: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("YAML nested too deep"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("bad file"), std::string::npos) << msg;
  // Ten levels are fine.
  EXPECT_EQ(errorOf("b: " + std::string(10, '[') + std::string(10, ']') + "\n"), "");
}

TEST(YamlLimits, OversizeTextAndFileAreRefusedNamingTheLimit) {
  const std::string big = "a: 1\n" + std::string(kMaxConfigBytes, '#') + "\n";
  const std::string msg = errorOf(big);
  EXPECT_EQ(msg, "f.yaml:1: " + std::to_string(big.size()) + " bytes is more than a configuration file can be (256 KB)");

  const std::filesystem::path path = std::filesystem::temp_directory_path() / "simswift_test_oversize.yaml";
  {
    std::ofstream out(path);
    out << big;
  }
  const std::string file_msg = simswift::testing::configError([&] { YamlReader::parseFile(path.string()); });
  EXPECT_EQ(file_msg.rfind(path.string() + ":1: ", 0), 0u) << file_msg;
  EXPECT_NE(file_msg.find("(256 KB)"), std::string::npos) << file_msg;
  std::filesystem::remove(path);

  // At the limit exactly: read.
  std::string full = "a: 1\n";
  full += std::string(kMaxConfigBytes - full.size() - 1, '#') + "\n";
  ASSERT_EQ(full.size(), kMaxConfigBytes);
  EXPECT_EQ(errorOf(full), "");
}

TEST(YamlLimits, AliasesCountAtEveryUse) {
  // An alias is the node it names: counted in full wherever it is used.
  EXPECT_EQ(expandedNodes(YamlReader::parse("[1, 2]", "f.yaml"), 100), 3u);
  EXPECT_EQ(expandedNodes(YamlReader::parse("a: &x [1, 2]\nb: *x\n", "f.yaml"), 100), 9u);
  // Ordinary aliases (the shipped experiments share robots lists) load.
  EXPECT_EQ(errorOf("a: &r [{x: 1}, {x: 2}]\nb: *r\nc: *r\n"), "");

  // Ten lists of the one before, each of ten: 10^8 nodes in 600 bytes.
  std::string bomb = "l0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int i = 1; i < 8; ++i) {
    const std::string prev = "*l" + std::to_string(i - 1);
    bomb += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += (k ? ", " : "") + prev;
    bomb += "]\n";
  }
  const std::string msg = errorOf(bomb);
  EXPECT_EQ(msg.rfind("f.yaml:1: more than " + std::to_string(kMaxConfigNodes) + " YAML nodes", 0), 0u) << msg;
  EXPECT_NE(msg.find("alias"), std::string::npos) << msg;
}

TEST(YamlLimits, ALongUnknownKeyIsShownCut) {
  // Keys over 1024 characters are not plain keys to yaml-cpp; one of 1000 is.
  const std::string key(1000, 'k');
  const YAML::Node root = YamlReader::parse("a: 1\n" + key + ": 2\n", "f.yaml");
  YamlReader top(root, "f.yaml");
  top.number("a");
  const std::string msg = simswift::testing::configError([&] { top.finish(); });
  EXPECT_EQ(msg.rfind("f.yaml:2: unknown key '" + std::string(80, 'k') + "...(1000 bytes)' in <document>", 0), 0u)
      << msg;
}
