// The MCAP reader (Mcap.hpp). Record layouts: https://mcap.dev/spec
// (little-endian; String = uint32 length + bytes; Map = uint32 byte length +
// key/value Strings; a record = uint8 opcode + uint64 content length +
// content).
#include "app/view/Mcap.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/mcap/Format.hpp"

namespace simswift::view {

namespace {

using namespace common::mcap;  // the magic, the record opcodes, crc32 (mcap.dev/spec)
constexpr std::uint8_t kMaxOp = kDataEnd;  // higher opcodes: 0x80+ are private records (skipped), the rest unknown

}  // namespace

McapError::McapError(const std::string& file, std::uint64_t offset, const std::string& what)
    : std::runtime_error(file + ": byte " + std::to_string(offset) + ": " + what), offset_(offset) {}

// Reads fields from [pos, end) of the file's bytes; every read is checked
// against `end` (the enclosing record's end), offsets are the file's.
class Cursor {
 public:
  Cursor(const McapFile& f, std::uint64_t pos, std::uint64_t end, const char* what)
      : f_(f), pos_(pos), end_(end), what_(what) {}
  std::uint64_t pos() const { return pos_; }
  std::uint64_t left() const { return end_ - pos_; }
  [[noreturn]] void fail(const std::string& msg, std::uint64_t at) const { throw McapError(f_.name(), at, msg); }
  void need(std::uint64_t n, const char* field) const {
    if (n > left())
      fail(std::string(what_) + ": " + field + " needs " + std::to_string(n) + " bytes, the record has " +
               std::to_string(left()) + " left",
           pos_);
  }
  template <class T>
  T uint(const char* field) {
    need(sizeof(T), field);
    T v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      v |= static_cast<T>(static_cast<T>(static_cast<unsigned char>(f_.bytes()[pos_ + i])) << (8 * i));
    pos_ += sizeof(T);
    return v;
  }
  std::string_view bytes(std::uint64_t n, const char* field) {
    need(n, field);
    std::string_view v = std::string_view(f_.bytes()).substr(pos_, n);
    pos_ += n;
    return v;
  }
  std::string string(const char* field) {
    const std::uint32_t n = uint<std::uint32_t>(field);
    return std::string(bytes(n, field));
  }
  std::map<std::string, std::string> map(const char* field) {
    const std::uint32_t n = uint<std::uint32_t>(field);
    need(n, field);
    Cursor inner(f_, pos_, pos_ + n, what_);
    std::map<std::string, std::string> m;
    while (inner.left() > 0) {
      std::string k = inner.string(field);
      m[k] = inner.string(field);
    }
    pos_ += n;
    return m;
  }

 private:
  const McapFile& f_;
  std::uint64_t pos_, end_;
  const char* what_;
};

// Scans the records of [begin, end): the data section, or a chunk's records.
class McapScanner {
 public:
  explicit McapScanner(McapFile& f) : f_(f) {}

  void scanFile() {
    const std::string& b = f_.bytes_;
    if (b.size() < 8 || std::memcmp(b.data(), kMagic, 8) != 0)
      throw McapError(f_.name_, 0, b.size() < 8 ? "too short for MCAP's magic bytes" : "not an MCAP file (no magic bytes)");
    if (b.size() < 16 || std::memcmp(b.data() + b.size() - 8, kMagic, 8) != 0)
      throw McapError(f_.name_, b.size(),
                      "no closing magic bytes: the file is truncated (a recording cut short?) or not MCAP");
    const std::uint64_t end = b.size() - 8;
    std::uint64_t pos = 8;
    bool first = true, footer = false;
    while (pos < end) {
      if (footer) throw McapError(f_.name_, pos, "records after the footer");
      const Record r = record(pos, end);
      if (first && r.op != kHeader) throw McapError(f_.name_, pos, "the first record is not a header");
      first = false;
      switch (r.op) {
        case kHeader: {
          Cursor c(f_, r.content, r.end, "header");
          f_.profile_ = c.string("profile");
          f_.library_ = c.string("library");
          break;
        }
        case kFooter:
          footer = true;
          break;
        case kDataEnd:
          summary_ = true;  // what follows repeats the data section's schemas and channels: skipped
          break;
        case kChunk:
          if (!summary_) chunk(r);
          break;
        case 0x0C:  // Metadata
          if (!summary_) metadata(r);
          break;
        default:
          if (!summary_) inner(r);
      }
      pos = r.end;
    }
    if (!footer) throw McapError(f_.name_, end, "no footer record before the closing magic bytes");
    for (auto& [id, list] : f_.messages_) {
      const auto earlier = [](const McapMessage& a, const McapMessage& b) { return a.log_time < b.log_time; };
      if (!std::is_sorted(list.begin(), list.end(), earlier)) std::stable_sort(list.begin(), list.end(), earlier);
      if (list.empty()) continue;
      f_.start_ = f_.count_ == 0 ? list.front().log_time : std::min(f_.start_, list.front().log_time);
      f_.end_ = f_.count_ == 0 ? list.back().log_time : std::max(f_.end_, list.back().log_time);
      f_.count_ += list.size();
    }
  }

 private:
  struct Record {
    std::uint8_t op;
    std::uint64_t content, end;
  };

  Record record(std::uint64_t pos, std::uint64_t end) {
    Cursor c(f_, pos, end, "record");
    if (end - pos < 9)
      c.fail("a record's opcode and length need 9 bytes, " + std::to_string(end - pos) + " left (truncated)", pos);
    Record r{};
    r.op = c.uint<std::uint8_t>("opcode");
    const std::uint64_t length = c.uint<std::uint64_t>("length");
    if (length > c.left())
      c.fail("record (opcode 0x" + hex(r.op) + ") of " + std::to_string(length) + " bytes runs past its end (" +
                 std::to_string(c.left()) + " bytes left: truncated?)",
             pos);
    r.content = c.pos();
    r.end = r.content + length;
    return r;
  }

  static std::string hex(unsigned v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
  }

  // A record allowed in the data section and in a chunk: schema, channel,
  // message; the other known ones (indexes, attachments, statistics) are
  // skipped, as are private ones (0x80 and up).
  void inner(const Record& r) {
    switch (r.op) {
      case kSchema: {
        Cursor c(f_, r.content, r.end, "schema");
        McapSchema s;
        s.id = c.uint<std::uint16_t>("id");
        s.name = c.string("name");
        s.encoding = c.string("encoding");
        s.data = c.string("data");
        if (s.id == 0) c.fail("schema id 0 is reserved", r.content);
        f_.schemas_[s.id] = std::move(s);
        break;
      }
      case kChannel: {
        Cursor c(f_, r.content, r.end, "channel");
        McapChannel ch;
        ch.id = c.uint<std::uint16_t>("id");
        ch.schema_id = c.uint<std::uint16_t>("schema_id");
        ch.topic = c.string("topic");
        ch.message_encoding = c.string("message_encoding");
        ch.metadata = c.map("metadata");
        if (ch.schema_id != 0 && !f_.schemas_.count(ch.schema_id))
          c.fail("channel '" + ch.topic + "' names schema " + std::to_string(ch.schema_id) + ", not defined before it",
                 r.content);
        f_.messages_[ch.id];
        f_.channels_[ch.id] = std::move(ch);
        break;
      }
      case kMessage: {
        Cursor c(f_, r.content, r.end, "message");
        McapMessage m;
        const std::uint16_t channel = c.uint<std::uint16_t>("channel_id");
        m.sequence = c.uint<std::uint32_t>("sequence");
        m.log_time = c.uint<std::uint64_t>("log_time");
        c.uint<std::uint64_t>("publish_time");
        if (!f_.channels_.count(channel))
          c.fail("message on channel " + std::to_string(channel) + ", not defined before it", r.content);
        if (c.left() > 0xFFFFFFFFu) c.fail("message larger than 4 GiB", r.content);
        m.offset = c.pos();
        m.length = static_cast<std::uint32_t>(c.left());
        f_.messages_[channel].push_back(m);
        break;
      }
      case kHeader:
      case kFooter:
      case kChunk:
      case kDataEnd:
        throw McapError(f_.name_, r.content - 9, "record (opcode 0x" + hex(r.op) + ") out of place");
      default:
        if (r.op == 0 || (r.op > kMaxOp && r.op < 0x80))
          throw McapError(f_.name_, r.content - 9, "unknown record opcode 0x" + hex(r.op));
    }
  }

  void chunk(const Record& r) {
    Cursor c(f_, r.content, r.end, "chunk");
    c.uint<std::uint64_t>("message_start_time");
    c.uint<std::uint64_t>("message_end_time");
    const std::uint64_t uncompressed = c.uint<std::uint64_t>("uncompressed_size");
    const std::uint32_t crc = c.uint<std::uint32_t>("uncompressed_crc");
    const std::uint64_t at = c.pos();
    const std::string compression = c.string("compression");
    if (!compression.empty())
      c.fail("chunk compressed with '" + compression + "': this reader takes uncompressed chunks only", at);
    const std::uint64_t length = c.uint<std::uint64_t>("records length");
    const std::uint64_t begin = c.pos();
    c.bytes(length, "records");
    if (length != uncompressed)
      c.fail("chunk of " + std::to_string(length) + " bytes says it holds " + std::to_string(uncompressed), at);
    if (crc != 0 && crc32(0, f_.bytes_.data() + begin, length) != crc)
      c.fail("chunk's CRC does not match its records (corrupt)", begin);
    for (std::uint64_t pos = begin; pos < begin + length;) {
      const Record inside = record(pos, begin + length);
      inner(inside);
      pos = inside.end;
    }
  }

  void metadata(const Record& r) {
    Cursor c(f_, r.content, r.end, "metadata");
    std::string name = c.string("name");
    f_.metadata_[name] = c.map("metadata");
  }

  McapFile& f_;
  bool summary_ = false;
};

McapFile McapFile::parse(std::string bytes, const std::string& name) {
  McapFile f;
  f.name_ = name;
  f.bytes_ = std::move(bytes);
  McapScanner(f).scanFile();
  return f;
}

McapFile McapFile::open(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw McapError(path, 0, "is a folder, not a recording");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw McapError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  const std::streamoff size = in.tellg();
  if (size < 0 || !std::filesystem::is_regular_file(path, ec))
    throw McapError(path, 0, "not a regular file (a recording is read whole, with its size known)");
  std::string bytes(static_cast<std::size_t>(size), '\0');  // read once, into its final place
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw McapError(path, static_cast<std::uint64_t>(in.gcount()), "read error");
  return parse(std::move(bytes), path);
}

const McapChannel* McapFile::channelOf(const std::string& topic) const {
  for (const auto& [id, ch] : channels_)
    if (ch.topic == topic) return &ch;
  return nullptr;
}

}  // namespace simswift::view
