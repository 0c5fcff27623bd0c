// The viewer's MCAP reader (app/view/Mcap.hpp): a file built here record by
// record (https://mcap.dev/spec) is read back; every truncation of it and
// a set of hostile records give an McapError naming the file and the byte,
// never a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "app/view/Json.hpp"
#include "app/view/Mcap.hpp"
#include "app/view/ViewerSite.hpp"
#include "tests/view/McapBytes.hpp"

namespace simswift::view {
namespace {

using namespace testing;

// A file with a schema, two channels, messages in and out of a chunk (one out of time order) and metadata.
std::string goodFile() {
  return kMagic + header() + schema(1) + channel(1, 1, "/tf") + metadata() +
         chunk(channel(2, 1, "/events") + message(1, 20, "{\"a\":2}") + message(2, 15, "{\"e\":1}")) +
         message(1, 10, "{\"a\":1}") + message(1, 30, " [1, 2.5e3, true, null, \"x\\u0041\"] ") + tail();
}

TEST(McapReader, ReadsSchemasChannelsMessagesAndMetadata) {
  const McapFile f = McapFile::parse(goodFile(), "good.mcap");
  EXPECT_EQ(f.library(), "test");
  ASSERT_EQ(f.channels().size(), 2u);
  ASSERT_NE(f.channelOf("/events"), nullptr);
  EXPECT_EQ(f.schemas().at(1).name, "s.Thing");
  EXPECT_EQ(f.metadata().at("simswift").at("scenario"), "walk_one.yaml");
  const auto& tf = f.messages().at(1);
  ASSERT_EQ(tf.size(), 3u);
  EXPECT_EQ(tf[0].log_time, 10u);  // sorted by log time
  EXPECT_EQ(f.payload(tf[0]), "{\"a\":1}");
  EXPECT_EQ(f.payload(tf[1]), "{\"a\":2}");
  EXPECT_EQ(f.messageCount(), 4u);
  EXPECT_EQ(f.startTime(), 10u);
  EXPECT_EQ(f.endTime(), 30u);
  EXPECT_NO_THROW(checkPayloads(f));
}

// Every prefix of a good file (a recording cut short) is refused with the file's name.
TEST(McapReader, EveryTruncationIsAnErrorNamingTheFile) {
  const std::string good = goodFile();
  for (std::size_t n = 0; n < good.size(); ++n) {
    try {
      McapFile::parse(good.substr(0, n), "cut.mcap");
      ADD_FAILURE() << "a file cut at " << n << " bytes was read";
    } catch (const McapError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.mcap: byte ", 0), 0u) << e.what();
      EXPECT_LE(e.offset(), n);
    }
  }
}

// Hostile files: the error names the byte of the bad field or record.
void expectError(const std::string& bytes, std::uint64_t offset, const std::string& words) {
  try {
    McapFile::parse(bytes, "bad.mcap");
    ADD_FAILURE() << "read a file that should fail with '" << words << "'";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), offset) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(McapReader, HostileRecordsAreRefusedWhereTheyAre) {
  const std::size_t body = kMagic.size() + header().size();  // where the first record after the header starts
  expectError("not an mcap file at all", 0, "not an MCAP file");
  // A record claiming 2^64-1 bytes.
  expectError(kMagic + header() + Bytes().u8(0x05).u64(~0ull).b + tail(), body, "runs past its end");
  // A string longer than its record.
  expectError(kMagic + header() + record(0x03, Bytes().u16(1).u32(1000).raw("abc").b) + tail(), body + 9 + 2 + 4,
              "name needs 1000 bytes");
  // A message before its channel; a channel naming an unknown schema.
  expectError(kMagic + header() + message(9, 1, "{}") + tail(), body + 9, "channel 9, not defined");
  expectError(kMagic + header() + channel(1, 4, "/x") + tail(), body + 9, "schema 4");
  // A compressed chunk, a chunk whose CRC is wrong, a header inside a chunk.
  expectError(kMagic + header() + chunk(schema(1), "zstd") + tail(), body + 9 + 28, "'zstd'");
  expectError(kMagic + header() + chunk(schema(1), "", false) + tail(), body + 9 + 40, "CRC");
  expectError(kMagic + header() + chunk(header()) + tail(), body + 9 + 40, "out of place");
  // No header first; records after the footer; an unknown opcode.
  expectError(kMagic + schema(1) + tail(), 8, "not a header");
  expectError(kMagic + header() + record(0x02, Bytes().u64(0).u64(0).u32(0).b) + schema(1) + kMagic,
              body + 9 + 20, "after the footer");
  expectError(kMagic + header() + record(0x42, "") + tail(), body, "unknown record opcode 0x42");
}

TEST(McapReader, APayloadThatIsNotJsonIsNamedByItsByte) {
  const std::string prefix = kMagic + header() + schema(1) + channel(1, 1, "/tf");
  const McapFile f = McapFile::parse(prefix + message(1, 5, "{\"x\": 1,}") + tail(), "bad.mcap");
  try {
    checkPayloads(f);
    ADD_FAILURE() << "a payload that is not JSON passed";
  } catch (const McapError& e) {
    EXPECT_EQ(e.offset(), prefix.size() + 9 + 22 + 8) << e.what();  // the '}' after the comma
    EXPECT_NE(std::string(e.what()).find("'/tf'"), std::string::npos) << e.what();
  }
}

TEST(Json, Validates) {
  EXPECT_EQ(json::invalidAt("{\"a\": [1, -0.5e-3, {}, []], \"b\": \"\\n\"}"), std::string_view::npos);
  EXPECT_EQ(json::invalidAt(""), 0u);
  EXPECT_EQ(json::invalidAt("[1,]"), 3u);
  EXPECT_EQ(json::invalidAt("01"), 1u);
  EXPECT_EQ(json::invalidAt("\"a\nb\""), 2u);
  EXPECT_EQ(json::invalidAt("{} x"), 3u);
  EXPECT_NE(json::invalidAt(std::string(200, '[') + std::string(200, ']')), std::string_view::npos);  // too deep
}

}  // namespace
}  // namespace simswift::view
