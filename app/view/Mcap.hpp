// An MCAP file read whole into memory (the format: https://mcap.dev/spec),
// for `simswift view` (docs/viewer.md). A reader of our own: it scans the
// data section once, front to back (time linear in the file's size), checks
// every length and offset against what holds it before reading, and keeps
// the schemas, channels, metadata and an index of each channel's messages
// (their log times and where their bytes are). Chunks must be uncompressed
// (simswift's recorder writes them so); any other compression is refused.
// Anything malformed is an McapError naming the file and the byte offset.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace simswift::view {

class McapError : public std::runtime_error {
 public:
  McapError(const std::string& file, std::uint64_t offset, const std::string& what);
  std::uint64_t offset() const { return offset_; }

 private:
  std::uint64_t offset_;
};

struct McapSchema {
  std::uint16_t id = 0;
  std::string name, encoding, data;
};

struct McapChannel {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, message_encoding;
  std::map<std::string, std::string> metadata;
};

// One message: its log time (ns; simswift's: simulated ns since the run's
// start) and where its payload is in McapFile::bytes().
struct McapMessage {
  std::uint64_t log_time = 0;
  std::uint64_t offset = 0;  // of the payload in the file
  std::uint32_t length = 0;
  std::uint32_t sequence = 0;
};

class McapFile {
 public:
  // Reads and indexes `path`; McapError if it cannot be read or is malformed.
  static McapFile open(const std::string& path);
  // The same from bytes in memory (`name` is what errors call it).
  static McapFile parse(std::string bytes, const std::string& name);

  const std::string& name() const { return name_; }
  const std::string& bytes() const { return bytes_; }
  std::string_view payload(const McapMessage& m) const { return std::string_view(bytes_).substr(m.offset, m.length); }

  const std::string& profile() const { return profile_; }
  const std::string& library() const { return library_; }
  const std::map<std::uint16_t, McapSchema>& schemas() const { return schemas_; }
  const std::map<std::uint16_t, McapChannel>& channels() const { return channels_; }
  // Metadata records by name (a later record of the same name replaces).
  const std::map<std::string, std::map<std::string, std::string>>& metadata() const { return metadata_; }
  // Each channel's messages, in log-time order (stable: file order on ties).
  const std::map<std::uint16_t, std::vector<McapMessage>>& messages() const { return messages_; }
  // The channel of a topic, or nullptr (the first channel if several share it).
  const McapChannel* channelOf(const std::string& topic) const;
  std::uint64_t startTime() const { return start_; }  // ns; 0 if no message
  std::uint64_t endTime() const { return end_; }
  std::size_t messageCount() const { return count_; }

 private:
  friend class McapScanner;
  std::string name_, bytes_, profile_, library_;
  std::map<std::uint16_t, McapSchema> schemas_;
  std::map<std::uint16_t, McapChannel> channels_;
  std::map<std::string, std::map<std::string, std::string>> metadata_;
  std::map<std::uint16_t, std::vector<McapMessage>> messages_;
  std::uint64_t start_ = 0, end_ = 0;
  std::size_t count_ = 0;
};

}  // namespace simswift::view
