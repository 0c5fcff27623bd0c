// The one seed reader: every 64-bit value, exactly, and nothing else; a
// robot's setup file carries the largest seed there and back unchanged.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "common/config/Seed.hpp"
#include "agent/program/RobotSetup.hpp"

namespace {

using common::config::parseSeed;

TEST(Seed, EverySixtyFourBitValueExactly) {
  EXPECT_EQ(parseSeed("0"), 0u);
  EXPECT_EQ(parseSeed("18446744073709551615"), UINT64_MAX);
  EXPECT_EQ(parseSeed("9007199254740993"), 9007199254740993u);  // 2^53 + 1: a double would round it
  EXPECT_EQ(parseSeed("0018446744073709551615"), std::nullopt);    // over 20 characters
  EXPECT_EQ(parseSeed("18446744073709551616"), std::nullopt);      // 2^64
  EXPECT_EQ(parseSeed("99999999999999999999"), std::nullopt);
  for (const char* bad : {"", "-1", "+1", "1e3", "1.0", " 1", "1 ", "0x10", "seed"})
    EXPECT_EQ(parseSeed(bad), std::nullopt) << bad;
}

TEST(Seed, TheLargestRoundTripsThroughARobotsSetupFile) {
  agent::program::RobotSetup s;
  s.team = 19;
  s.player = 2;
  s.seed = UINT64_MAX;
  const std::string path = std::string(SIMSWIFT_BINARY_DIR) + "/seed_round_trip.robot.yaml";
  std::ofstream(path) << agent::program::robotSetupYaml(s);
  EXPECT_EQ(agent::program::readRobotSetup(path).seed, UINT64_MAX);
  std::filesystem::remove(path);
}

}  // namespace
