// A writer of MCAP files (the format's public specification, mcap.dev/spec,
// major version 0), written for simswift: magic, Header, then the data
// section (Schema, Channel and Metadata records outside chunks; Message
// records in uncompressed Chunks, each followed by its Message Index
// records), DataEnd, the Summary section (Schemas, Channels, Statistics,
// Metadata Index, Chunk Index), one Summary Offset per summary group, Footer,
// magic. Integers little-endian. Nothing here reads a clock: the same calls
// give the same bytes.
//
// Order rule: schemas, channels and metadata are written outside chunks, so
// adding one closes the open chunk first (a streaming reader sees every
// channel before its messages).
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace simswift::record {

// A file that cannot be written (the message names the path).
struct RecordError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class McapWriter {
 public:
  using StringMap = std::vector<std::pair<std::string, std::string>>;  // written in this order

  // Opens `path` for writing (truncates) and writes the magic and the Header
  // (profile "", library `library`). A chunk is closed once its records pass
  // `chunk_bytes`. Throws RecordError.
  McapWriter(const std::string& path, const std::string& library, size_t chunk_bytes = 1 << 20);
  ~McapWriter();  // close()s, swallowing errors (call close() to see them)
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Returns the schema's id (1, 2, ...). encoding e.g. "jsonschema".
  uint16_t addSchema(const std::string& name, const std::string& encoding, std::string_view data);
  // Returns the channel's id (0, 1, ...); schema_id 0 = no schema.
  uint16_t addChannel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                      const StringMap& metadata = {});
  void addMetadata(const std::string& name, const StringMap& metadata);
  // One message; log_time = publish_time = time_ns (ns). Times must not
  // decrease across calls (the chunks' time ranges rely on it).
  void write(uint16_t channel, uint64_t time_ns, std::string_view data);
  // Writes the rest of the file and closes it. Idempotent. Throws RecordError.
  void close();

  const std::string& path() const { return path_; }
  uint64_t messageCount() const { return message_count_; }
  uint64_t bytesWritten() const { return pos_; }

 private:
  struct ChunkIndex {
    uint64_t start_time, end_time, chunk_offset, chunk_length, index_length, records_size;
    std::vector<std::pair<uint16_t, uint64_t>> index_offsets;  // channel -> file offset of its Message Index
  };
  void put(const std::string& bytes);  // appends to the file, counts pos_
  void flushChunk();
  void fail(const std::string& what) const;

  std::string path_;
  std::FILE* file_ = nullptr;
  size_t chunk_bytes_;
  uint64_t pos_ = 0;  // bytes written so far
  bool closed_ = false;
  std::vector<std::string> schema_records_, channel_records_;  // record bodies, repeated in the summary
  std::vector<std::pair<std::string, std::pair<uint64_t, uint64_t>>> metadata_;  // name, (offset, length)
  std::vector<ChunkIndex> chunk_indexes_;
  // The open chunk: its records, its time range and per channel its
  // messages' (log time, offset in the records).
  std::string chunk_;
  uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;
  std::vector<uint32_t> sequence_;  // per channel
  std::vector<uint64_t> channel_counts_;  // messages per channel
  uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;
};

}  // namespace simswift::record
