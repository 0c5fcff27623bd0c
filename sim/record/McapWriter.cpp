#include "sim/record/McapWriter.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <tuple>

#include "common/mcap/Format.hpp"

namespace simswift::record {
namespace {

using namespace common::mcap;  // the magic, the record opcodes, crc32 (mcap.dev/spec)

// Little-endian field writers (the spec's primitive types).
void u8(std::string& s, uint8_t v) { s.push_back(static_cast<char>(v)); }
template <typename T>
void le(std::string& s, T v) {
  for (size_t i = 0; i < sizeof(T); ++i) s.push_back(static_cast<char>((static_cast<uint64_t>(v) >> (8 * i)) & 0xff));
}
void u16(std::string& s, uint16_t v) { le(s, v); }
void u32(std::string& s, uint32_t v) { le(s, v); }
void u64(std::string& s, uint64_t v) { le(s, v); }
void str(std::string& s, std::string_view v) {  // uint32 length, then the bytes
  u32(s, static_cast<uint32_t>(v.size()));
  s.append(v.data(), v.size());
}
void stringMap(std::string& s, const McapWriter::StringMap& m) {  // uint32 byte length, then the pairs
  std::string body;
  for (const auto& [k, v] : m) {
    str(body, k);
    str(body, v);
  }
  u32(s, static_cast<uint32_t>(body.size()));
  s += body;
}
// <opcode><uint64 length><body>
std::string record(uint8_t op, const std::string& body) {
  std::string r;
  r.reserve(body.size() + 9);
  u8(r, op);
  u64(r, body.size());
  r += body;
  return r;
}

}  // namespace


McapWriter::McapWriter(const std::string& path, const std::string& library, size_t chunk_bytes)
    : path_(path), chunk_bytes_(chunk_bytes) {
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) fail(std::string("cannot open for writing: ") + std::strerror(errno));
  put(std::string(kMagic, sizeof kMagic));
  std::string h;
  str(h, "");  // profile: none (simswift's own topics, JSON messages)
  str(h, library);
  put(record(kHeader, h));
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (const RecordError&) {
  }
}

void McapWriter::fail(const std::string& what) const { throw RecordError("recording " + path_ + ": " + what); }

void McapWriter::put(const std::string& bytes) {
  if (!file_) fail("written after close");
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail(std::string("write failed: ") + std::strerror(errno));
  pos_ += bytes.size();
}

uint16_t McapWriter::addSchema(const std::string& name, const std::string& encoding, std::string_view data) {
  if (schema_records_.size() >= 0xfffe) fail("too many schemas");
  flushChunk();
  const auto id = static_cast<uint16_t>(schema_records_.size() + 1);  // 0 means "no schema"
  std::string b;
  u16(b, id);
  str(b, name);
  str(b, encoding);
  str(b, data);  // uint32 length-prefixed bytes
  schema_records_.push_back(b);
  put(record(kSchema, b));
  return id;
}

uint16_t McapWriter::addChannel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                                const StringMap& metadata) {
  if (channel_records_.size() >= 0xffff) fail("too many channels");
  if (schema_id > schema_records_.size()) fail("channel " + topic + ": no schema " + std::to_string(schema_id));
  flushChunk();
  const auto id = static_cast<uint16_t>(channel_records_.size());
  std::string b;
  u16(b, id);
  u16(b, schema_id);
  str(b, topic);
  str(b, message_encoding);
  stringMap(b, metadata);
  channel_records_.push_back(b);
  sequence_.push_back(0);
  channel_counts_.push_back(0);
  put(record(kChannel, b));
  return id;
}

void McapWriter::addMetadata(const std::string& name, const StringMap& metadata) {
  flushChunk();
  std::string b;
  str(b, name);
  stringMap(b, metadata);
  const std::string r = record(kMetadata, b);
  metadata_.push_back({name, {pos_, r.size()}});
  put(r);
}

void McapWriter::write(uint16_t channel, uint64_t time_ns, std::string_view data) {
  if (closed_) fail("message after close");
  if (channel >= channel_records_.size()) fail("message on unknown channel " + std::to_string(channel));
  if (message_count_ > 0 && time_ns < last_time_) fail("message times must not decrease");
  if (chunk_.empty()) chunk_start_ = time_ns;
  chunk_end_ = time_ns;
  chunk_index_[channel].push_back({time_ns, chunk_.size()});
  u8(chunk_, kMessage);
  u64(chunk_, 2 + 4 + 8 + 8 + data.size());
  u16(chunk_, channel);
  u32(chunk_, sequence_[channel]++);
  u64(chunk_, time_ns);  // log_time
  u64(chunk_, time_ns);  // publish_time
  chunk_.append(data.data(), data.size());
  if (message_count_ == 0) first_time_ = time_ns;
  last_time_ = time_ns;
  ++message_count_;
  ++channel_counts_[channel];
  if (chunk_.size() >= chunk_bytes_) flushChunk();
}

// The open chunk (uncompressed), then its Message Index records, one per
// channel in it, by channel id.
void McapWriter::flushChunk() {
  if (chunk_.empty()) return;
  std::string b;
  u64(b, chunk_start_);
  u64(b, chunk_end_);
  u64(b, chunk_.size());                                // uncompressed_size
  u32(b, crc32(0, chunk_.data(), chunk_.size()));       // uncompressed_crc
  str(b, "");                                           // compression: none
  u64(b, chunk_.size());                                // records, uint64 length-prefixed
  b += chunk_;
  ChunkIndex ci{chunk_start_, chunk_end_, pos_, 0, 0, chunk_.size(), {}};
  const std::string r = record(kChunk, b);
  ci.chunk_length = r.size();
  put(r);
  const uint64_t index_start = pos_;
  for (const auto& [channel, entries] : chunk_index_) {
    std::string m;
    u16(m, channel);
    u32(m, static_cast<uint32_t>(entries.size() * 16));
    for (const auto& [t, offset] : entries) {
      u64(m, t);
      u64(m, offset);
    }
    ci.index_offsets.push_back({channel, pos_});
    put(record(kMessageIndex, m));
  }
  ci.index_length = pos_ - index_start;
  chunk_indexes_.push_back(std::move(ci));
  chunk_.clear();
  chunk_index_.clear();
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  flushChunk();
  std::string d;
  u32(d, 0);  // data_section_crc: 0, "not available" (the chunks carry their own)
  put(record(kDataEnd, d));

  // The summary section: one group per record kind; a Summary Offset for each.
  const uint64_t summary_start = pos_;
  std::string summary;
  std::vector<std::tuple<uint8_t, uint64_t, uint64_t>> groups;  // opcode, start, length
  auto group = [&](uint8_t op, const std::vector<std::string>& bodies) {
    if (bodies.empty()) return;
    const uint64_t start = summary_start + summary.size();
    for (const std::string& body : bodies) summary += record(op, body);
    groups.emplace_back(op, start, summary_start + summary.size() - start);
  };
  group(kSchema, schema_records_);
  group(kChannel, channel_records_);
  {
    std::string s;
    u64(s, message_count_);
    u16(s, static_cast<uint16_t>(schema_records_.size()));
    u32(s, static_cast<uint32_t>(channel_records_.size()));
    u32(s, 0);  // attachments
    u32(s, static_cast<uint32_t>(metadata_.size()));
    u32(s, static_cast<uint32_t>(chunk_indexes_.size()));
    u64(s, first_time_);
    u64(s, last_time_);
    std::string counts;
    for (size_t c = 0; c < channel_counts_.size(); ++c) {
      u16(counts, static_cast<uint16_t>(c));
      u64(counts, channel_counts_[c]);
    }
    u32(s, static_cast<uint32_t>(counts.size()));
    s += counts;
    group(kStatistics, {s});
  }
  std::vector<std::string> bodies;
  for (const auto& [name, where] : metadata_) {
    std::string m;
    u64(m, where.first);
    u64(m, where.second);
    str(m, name);
    bodies.push_back(m);
  }
  group(kMetadataIndex, bodies);
  bodies.clear();
  for (const ChunkIndex& ci : chunk_indexes_) {
    std::string c;
    u64(c, ci.start_time);
    u64(c, ci.end_time);
    u64(c, ci.chunk_offset);
    u64(c, ci.chunk_length);
    std::string offsets;
    for (const auto& [channel, offset] : ci.index_offsets) {
      u16(offsets, channel);
      u64(offsets, offset);
    }
    u32(c, static_cast<uint32_t>(offsets.size()));
    c += offsets;
    u64(c, ci.index_length);
    str(c, "");             // compression
    u64(c, ci.records_size);  // compressed_size (= uncompressed: none)
    u64(c, ci.records_size);  // uncompressed_size
    bodies.push_back(c);
  }
  group(kChunkIndex, bodies);
  const uint64_t summary_offset_start = summary_start + summary.size();
  for (const auto& [op, start, length] : groups) {
    std::string o;
    u8(o, op);
    u64(o, start);
    u64(o, length);
    summary += record(kSummaryOffset, o);
  }
  // Footer: summary_crc covers the summary and summary offset sections and
  // the footer up to and including summary_offset_start.
  std::string footer_head;
  u8(footer_head, kFooter);
  u64(footer_head, 8 + 8 + 4);
  u64(footer_head, summary_start);
  u64(footer_head, summary_offset_start);
  uint32_t crc = crc32(0, summary.data(), summary.size());
  crc = crc32(crc, footer_head.data(), footer_head.size());
  put(summary);
  std::string tail = footer_head;
  u32(tail, crc);
  tail.append(kMagic, sizeof kMagic);
  put(tail);
  const bool ok = std::fflush(file_) == 0;
  const int err = errno;
  const bool closed_ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed_ok) fail(std::string("write failed: ") + std::strerror(err));
}

}  // namespace simswift::record
