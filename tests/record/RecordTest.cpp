// The recording (sim/record): the MCAP writer's bytes against the
// specification's layout, a recording of scenarios/walk_one.yaml read by
// the MCAP project's own reader (@mcap/core under node), and determinism
// (the same seed gives the same bytes, another seed other bytes).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "simswift/Simulation.hpp"
#include "common/mcap/Format.hpp"
#include "sim/record/McapWriter.hpp"
#include "sim/record/Recorder.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/record/NodeReader.hpp"
#include "tests/support/Shell.hpp"

namespace fs = std::filesystem;
using namespace simswift;
using simswift::testing::readText;
using simswift::testing::shell;

namespace {

std::string tempPath(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("simswift-record-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

uint64_t u64At(const std::string& b, size_t at) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | static_cast<uint8_t>(b[at + i]);
  return v;
}

// walk_one.yaml for `seconds` s (the push at 18 s and the fall after it
// need 20), inline programs, recorded at the default rate.
std::string recordWalk(const std::string& path, uint64_t seed, double seconds = 20) {
  runner::Scenario sc = runner::Scenario::loadFile(std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/walk_one.yaml");
  sc.duration = seconds;
  sc.seed = seed;
  runner::Runner r(sc);
  r.programs().setThreading(agent::program::Threading::Inline);
  record::Recorder rec(path);
  r.addObserver(&rec);
  runner::RunOptions o;
  o.progress = false;
  r.run(o);
  rec.finish();
  return bytesOf(path);
}

}  // namespace

TEST(McapWriter, FileLayoutFollowsTheSpecification) {
  const std::string path = tempPath("layout.mcap");
  {
    record::McapWriter w(path, "test", 64);  // small chunks: several
    const uint16_t s = w.addSchema("S", "jsonschema", "{}");
    const uint16_t c = w.addChannel(s, "/a", "json");
    for (int i = 0; i < 10; ++i) w.write(c, 1000 * i, "{\"i\":" + std::to_string(i) + "}");
    w.close();
  }
  const std::string b = bytesOf(path);
  const std::string magic("\x89MCAP0\r\n", 8);
  ASSERT_GT(b.size(), 2 * magic.size() + 29);
  EXPECT_EQ(b.substr(0, 8), magic);
  EXPECT_EQ(b.substr(b.size() - 8), magic);
  EXPECT_EQ(b[8], '\x01');  // Header first
  // Footer: opcode 0x02, length 20, then summary_start and
  // summary_offset_start, which point at a Schema record (the summary's
  // first group) and a Summary Offset record (0x0E).
  const size_t footer = b.size() - 8 - 29;
  EXPECT_EQ(b[footer], '\x02');
  EXPECT_EQ(u64At(b, footer + 1), 20u);
  const uint64_t summary = u64At(b, footer + 9), offsets = u64At(b, footer + 17);
  ASSERT_LT(summary, offsets);
  ASSERT_LT(offsets, footer);
  EXPECT_EQ(b[summary], '\x03');
  EXPECT_EQ(b[offsets], '\x0E');
  EXPECT_EQ(b[summary - 13], '\x0F');  // DataEnd (opcode, length 4, crc) just before the summary
  // The CRC table: crc32("123456789") is the standard check value.
  EXPECT_EQ(common::mcap::crc32(0, "123456789", 9), 0xCBF43926u);
}

TEST(McapWriter, RefusesWhatTheFormatCannotHold) {
  record::McapWriter w(tempPath("refuse.mcap"), "test");
  const uint16_t c = w.addChannel(0, "/a", "json");
  w.write(c, 10, "{}");
  EXPECT_THROW(w.write(c, 5, "{}"), record::RecordError);   // time going back
  EXPECT_THROW(w.write(7, 20, "{}"), record::RecordError);  // no such channel
  EXPECT_THROW(record::McapWriter("/nonexistent-dir/x.mcap", "t"), record::RecordError);
}

TEST(Recording, SameSeedSameBytesOtherSeedOtherBytes) {
  const std::string a = recordWalk(tempPath("a.mcap"), 1, 3);
  const std::string b = recordWalk(tempPath("b.mcap"), 1, 3);
  const std::string c = recordWalk(tempPath("c.mcap"), 2, 3);
  ASSERT_GT(a.size(), 10000u);
  EXPECT_TRUE(a == b) << "the same seed gave different recordings";
  EXPECT_FALSE(a == c) << "another seed (other sensor noise) gave the same recording";
}

// The whole contract of docs/recording.md as @mcap/core reads it.
TEST(Recording, WalkOneOpensInTheMcapProjectsReader) {
  std::string modules;
  const std::string why = simswift::testing::prepareMcapReader(modules);
  if (!why.empty()) {
    if (simswift::testing::nodeRequired()) FAIL() << why;
    GTEST_SKIP() << why;
  }
  const std::string path = tempPath("walk.mcap");
  recordWalk(path, 1, 20);
  const auto r = shell("node " + std::string(SIMSWIFT_SOURCE_DIR) + "/tests/record/mcap_check.cjs " + modules + " " +
                       path + " 2>&1");
  ASSERT_EQ(r.code, 0) << r.output;
  const std::string& j = r.output;
  auto has = [&](const std::string& text) { return j.find(text) != std::string::npos; };
  // Schemas, each JSON Schema; channels on them, JSON messages.
  for (const char* s : {"foxglove.FrameTransforms", "foxglove.SceneUpdate", "foxglove.Log", "simswift.JointState",
                        "simswift.Sensors", "simswift.TeamMessage"})
    EXPECT_TRUE(has(std::string("\"") + s + "\":\"jsonschema\"")) << s << "\n" << j.substr(0, 2000);
  for (const char* c : {R"("/tf":{"schema":"foxglove.FrameTransforms","encoding":"json"})",
                        R"("/scene":{"schema":"foxglove.SceneUpdate","encoding":"json"})",
                        R"("/events":{"schema":"foxglove.Log","encoding":"json"})",
                        R"("/robot0/joints":{"schema":"simswift.JointState","encoding":"json"})",
                        R"("/robot0/sensors":{"schema":"simswift.Sensors","encoding":"json"})",
                        R"("/team/sent":{"schema":"simswift.TeamMessage","encoding":"json"})",
                        R"("/robot0/belief":{"schema":"simswift.Belief","encoding":"json"})"})
    EXPECT_TRUE(has(c)) << c;
  // 20 s at 20 Hz: 401 samples (t = 0.01 s, then every 0.05 s to 20 s) of
  // poses, joints, sensors; one scene; both
  // readers count the same.
  for (const char* reader : {"stream", "indexed"}) {
    const std::string counts = R"("/scene":1)";
    std::smatch m;
    const std::regex section(std::string("\"") + reader + R"(":\{([^}]*)\})");
    ASSERT_TRUE(std::regex_search(j, m, section)) << reader;
    const std::string s = m[1];
    EXPECT_NE(s.find(R"("/tf":401)"), std::string::npos) << reader << ": " << s;
    EXPECT_NE(s.find(R"("/robot0/joints":401)"), std::string::npos) << reader << ": " << s;
    EXPECT_NE(s.find(R"("/robot0/sensors":401)"), std::string::npos) << reader << ": " << s;
    EXPECT_NE(s.find(R"("/robot0/belief":401)"), std::string::npos) << reader << ": " << s;
    EXPECT_NE(s.find(counts), std::string::npos) << reader << ": " << s;
  }
  EXPECT_TRUE(has(R"("stream_done":true)"));
  EXPECT_TRUE(has(R"("ordered":true)"));
  EXPECT_TRUE(has(R"("parse_errors":0)"));
  // Events: the scenario's push at 18 s, the fall it causes, the game state.
  EXPECT_TRUE(has(R"("game_state: game state playing")")) << j.substr(j.find("\"events\""), 1000);
  EXPECT_TRUE(has(R"("push: robot0: pushed (3.7, 0) N*s at the torso")")) << j.substr(j.find("\"events\""), 1000);
  EXPECT_TRUE(has(R"("fall: robot0: fell)")) << j.substr(j.find("\"events\""), 1000);
  // The metadata record: scenario, seed, robots with their links.
  EXPECT_TRUE(has(R"("seed":"1")"));
  EXPECT_TRUE(has(R"(walk_one.yaml)"));
  EXPECT_TRUE(has(R"(\"body\":\"V5\")"));
  EXPECT_TRUE(has(R"("child_frame_id":"robot0/)"));
  EXPECT_TRUE(has(R"("frame_id":"robot0/)"));
}

// The library's Simulation::record: the same recording as the Runner's
// observer gives, complete after finishRecording().
TEST(Recording, LibraryApiRecords) {
  const std::string path = tempPath("api.mcap");
  simswift::Simulation sim = simswift::Simulation::fromScenario(std::string(SIMSWIFT_SOURCE_DIR) +
                                                                 "/scenarios/walk_one.yaml");
  sim.record(path, 10);
  EXPECT_THROW(sim.record(tempPath("again.mcap")), std::logic_error);
  sim.run(1.0);
  sim.finishRecording();
  const std::string b = bytesOf(path);
  ASSERT_GT(b.size(), 16u);
  EXPECT_EQ(b.substr(b.size() - 8), std::string("\x89MCAP0\r\n", 8));
  size_t n = 0;
  for (size_t at = b.find("\"child_frame_id\":\"robot0/torso\""); at != std::string::npos;
       at = b.find("\"child_frame_id\":\"robot0/torso\"", at + 1))
    ++n;
  EXPECT_EQ(n, 11u);  // 0.01 s, then every 0.1 s to 1.0 s
  EXPECT_THROW(sim.record("/nonexistent-dir/x.mcap"), std::runtime_error);
}
