// YamlReader::readFile, the one reader of a configuration file's text (the
// robot's config, the field, the scenario): its errors name the path at
// line 1 and the kind of file; a file over kMaxConfigBytes is refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/config/YamlReader.hpp"

using common::config::ConfigError;
using common::config::kMaxConfigBytes;
using common::config::YamlReader;

namespace {

std::string readFileError(const std::string& path, const std::string& kind) {
  try {
    YamlReader::readFile(path, kind);
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file, path);
    EXPECT_EQ(e.line, 1);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ReadConfigFile, ReadsTheWholeText) {
  const std::string path = ::testing::TempDir() + "simswift_read_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(path) << "a: 1\nb: [2, 3]\n";
  EXPECT_EQ(YamlReader::readFile(path, "scenario file"), "a: 1\nb: [2, 3]\n");
  std::remove(path.c_str());
}

TEST(ReadConfigFile, ADirectoryOrAMissingFileIsNamedWithItsKind) {
  const std::string dir = ::testing::TempDir();
  EXPECT_EQ(readFileError(dir, "scenario file"), dir + ":1: is a directory, not a scenario file");
  EXPECT_EQ(readFileError(dir, "experiment file"), dir + ":1: is a directory, not an experiment file");
  EXPECT_EQ(readFileError(dir, "file"), dir + ":1: is a directory, not a file");
  EXPECT_EQ(readFileError("/no/such/s.yaml", "scenario file"), "/no/such/s.yaml:1: cannot open scenario file");
  EXPECT_EQ(readFileError("/no/such/c.yaml", "file"), "/no/such/c.yaml:1: cannot open file");
}

TEST(ReadConfigFile, AFileOverTheLimitIsRefused) {
  const std::string path = ::testing::TempDir() + "simswift_big_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(path) << std::string(kMaxConfigBytes + 1, '#');
  const std::string e = readFileError(path, "scenario file");
  EXPECT_EQ(e.rfind(path + ":1: " + std::to_string(kMaxConfigBytes + 1) + " bytes is more than", 0), 0u) << e;
  std::remove(path.c_str());
}
