// A LoLA client as a V6 team's program brings it, written only from the
// public LoLA clients of teams that ran them on real robots (B-Human's
// NaoProvider, HULKs' hula, rUNSWift 2019-2022's LoLAData.cpp, ros-sports/
// nao_lola) and msgpack's specification: no simswift header.
// It connects to a LoLA socket, reads 896-byte sensor packets, checks their
// keys, order, lengths and encodings, checks that the byte layout of every
// packet is the first packet's (B-Human's client reads later packets through
// offsets cached from the first), and answers each with Position and
// Stiffness.
//
//   lola-client SOCKET CYCLES [one-map | two-maps | split | limp | hold] [then-leave]
//
// Answers (LoLA joint order): Position[i] = 0.01 * i + 0.001 * cycle rad,
// Stiffness[i] = 0.5 ("limp": Stiffness only, 0; "hold": the first packet's
// Position, Stiffness 1, as a program that stands where it was put).
// "two-maps" sends Sonar [true, false] in a second map as rUNSWift 2022
// does; "split" writes the answer in three pieces 1 ms apart. SOCKET "-" is
// LoLA's own /tmp/robocup. Prints one line per packet:
//   packet N Position[10]=... FSR[0]=... Status[0]=... Accelerometer[2]=... FSRsum=... Gyroscope[2]=...
//            Accelerometer[0]=... Accelerometer[1]=... Position[9]=... Position[11]=...
// Exit 0 after CYCLES answered packets (CYCLES 0: until the server closes
// the socket, after at least one), 1 on any check failing, 2 on bad use.
// "then-leave": after CYCLES answers, read the next packet and close without
// answering it, as a program killed in the middle of a cycle.
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <msgpack.hpp>

namespace {

constexpr std::size_t kPacketBytes = 896;
// The 13 sensor keys and lengths (B-Human's NaoProvider, HULKs' hula), in
// real LoLA's order (a real V6's packet quoted in NaoTH's Tools/LolaData.h).
const std::vector<std::pair<std::string, std::size_t>> kKeys = {
    {"RobotConfig", 4}, {"Accelerometer", 3}, {"Angles", 2}, {"Battery", 4}, {"Current", 25},
    {"FSR", 8}, {"Gyroscope", 3}, {"Position", 25}, {"Sonar", 2}, {"Stiffness", 25},
    {"Temperature", 25}, {"Touch", 14}, {"Status", 25}};
const std::size_t kConfigLengths[4] = {20, 5, 20, 5};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "lola-client: %s\n", what.c_str());
  std::exit(1);
}

bool readAll(int fd, unsigned char* data, std::size_t size) {
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, data + got, size - got);
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

void writeAll(int fd, const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n <= 0) fail("write failed");
    done += static_cast<std::size_t>(n);
  }
}

// Byte offsets of every value payload in a packet: a float32's 4 bytes, a
// fixint's 1 byte. Walks the few msgpack forms LoLA uses, as B-Human's
// client does; anything else fails.
std::vector<std::pair<std::size_t, std::size_t>> valueOffsets(const unsigned char* p) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t i = 0;
  auto str = [&] {
    if ((p[i] & 0xe0) != 0xa0) fail("offset " + std::to_string(i) + ": expected a fixstr");
    i += 1 + (p[i] & 0x1f);
  };
  if ((p[0] & 0xf0) != 0x80) fail("not a fixmap");
  const int keys = p[i++] & 0x0f;
  for (int k = 0; k < keys; ++k) {
    str();
    std::size_t n;
    if ((p[i] & 0xf0) == 0x90) {
      n = p[i] & 0x0f;
      i += 1;
    } else if (p[i] == 0xdc) {
      n = (std::size_t(p[i + 1]) << 8) | p[i + 2];
      i += 3;
    } else {
      fail("offset " + std::to_string(i) + ": expected an array");
    }
    for (std::size_t e = 0; e < n; ++e) {
      if (i >= kPacketBytes) fail("walked past the packet");
      if (p[i] == 0xca) {
        out.push_back({i + 1, 4});
        i += 5;
      } else if (!(p[i] & 0x80)) {
        out.push_back({i, 1});
        i += 1;
      } else if ((p[i] & 0xe0) == 0xa0) {
        str();  // RobotConfig: part of the layout
      } else {
        fail("offset " + std::to_string(i) + ": unexpected byte");
      }
    }
  }
  if (i != kPacketBytes) fail("the map ends at " + std::to_string(i) + ", not at 896");
  return out;
}

float floatAt(const unsigned char* p) {
  const std::uint32_t bits = (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) |
                             (std::uint32_t(p[2]) << 8) | std::uint32_t(p[3]);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: lola-client SOCKET CYCLES [one-map|two-maps|split|limp|hold] [then-leave]\n");
    return 2;
  }
  const std::string path = std::string(argv[1]) == "-" ? "/tmp/robocup" : argv[1];
  const int cycles = std::atoi(argv[2]);
  const std::string mode = argc > 3 ? argv[3] : "one-map";
  if (mode != "one-map" && mode != "two-maps" && mode != "split" && mode != "limp" && mode != "hold") {
    std::fprintf(stderr, "lola-client: unknown mode %s\n", mode.c_str());
    return 2;
  }
  // Any other argument is ignored: a test's marker to find the process by.
  const bool then_leave = argc > 4 && std::string(argv[4]) == "then-leave";

  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof(address.sun_path) - 1);
  int tries = 0;
  // B-Human retries 10 times 10 ms apart; a test server may start a little later.
  while (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    if (++tries == 500) fail("cannot connect to " + path);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }

  unsigned char first[kPacketBytes];
  std::vector<std::pair<std::size_t, std::size_t>> offsets;
  std::vector<float> held;  // "hold": the first packet's Position
  for (int cycle = 0; cycles == 0 || cycle < cycles; ++cycle) {
    unsigned char packet[kPacketBytes];
    if (!readAll(fd, packet, kPacketBytes)) {
      if (cycles == 0 && cycle > 0) break;  // the run ended
      fail("the server closed the socket at packet " + std::to_string(cycle));
    }

    // msgpack-c's reading: one map, the keys in order, lengths and types.
    std::size_t off = 0;
    msgpack::object_handle handle = msgpack::unpack(reinterpret_cast<const char*>(packet), kPacketBytes, off);
    if (off != kPacketBytes) fail("the map is " + std::to_string(off) + " bytes, not 896");
    const msgpack::object& map = handle.get();
    if (map.type != msgpack::type::MAP || map.via.map.size != kKeys.size()) fail("not a map of 13 keys");
    std::map<std::string, std::vector<float>> values;
    for (std::size_t k = 0; k < kKeys.size(); ++k) {
      const msgpack::object_kv& kv = map.via.map.ptr[k];
      const std::string key = kv.key.as<std::string>();
      if (key != kKeys[k].first) fail("key " + std::to_string(k) + " is " + key + ", expected " + kKeys[k].first);
      if (kv.val.type != msgpack::type::ARRAY || kv.val.via.array.size != kKeys[k].second)
        fail(key + ": not an array of " + std::to_string(kKeys[k].second));
      for (std::size_t e = 0; e < kv.val.via.array.size; ++e) {
        const msgpack::object& v = kv.val.via.array.ptr[e];
        if (key == "RobotConfig") {
          if (v.type != msgpack::type::STR || v.via.str.size != kConfigLengths[e])
            fail("RobotConfig[" + std::to_string(e) + "]: not a string of " + std::to_string(kConfigLengths[e]));
          if ((e == 1 || e == 3) && v.via.str.ptr[0] != '6') fail("RobotConfig: not a version 6 robot");
        } else if (key == "Status") {
          if (v.type != msgpack::type::POSITIVE_INTEGER || v.via.u64 > 3) fail("Status: not 0..3");
          values[key].push_back(static_cast<float>(v.via.u64));
        } else {
          if (v.type != msgpack::type::FLOAT32) fail(key + ": not float32");
          values[key].push_back(static_cast<float>(v.via.f64));
        }
      }
    }

    // B-Human's way: offsets from the first packet, every later packet read through them.
    if (cycle == 0) {
      std::memcpy(first, packet, kPacketBytes);
      offsets = valueOffsets(first);
    }
    std::vector<bool> payload(kPacketBytes, false);
    for (const auto& [at, n] : offsets)
      for (std::size_t b = 0; b < n; ++b) payload[at + b] = true;
    for (std::size_t b = 0; b < kPacketBytes; ++b)
      if (!payload[b] && packet[b] != first[b])
        fail("packet " + std::to_string(cycle) + ": byte " + std::to_string(b) + " of the layout changed");
    // Position[10] (LKneePitch) through its cached offset agrees with msgpack-c.
    std::size_t position_first = 0;  // the values before Position's (RobotConfig's strings are layout)
    for (std::size_t k = 0; kKeys[k].first != "Position"; ++k)
      if (kKeys[k].first != "RobotConfig") position_first += kKeys[k].second;
    const float knee = floatAt(packet + offsets[position_first + 10].first);
    if (knee != values["Position"][10]) fail("cached offset and msgpack-c disagree");

    float fsr_sum = 0;
    for (float f : values["FSR"]) fsr_sum += f;
    std::printf("packet %d Position[10]=%.6g FSR[0]=%.6g Status[0]=%.0f Accelerometer[2]=%.6g FSRsum=%.6g "
                "Gyroscope[2]=%.6g Accelerometer[0]=%.6g Accelerometer[1]=%.6g Position[9]=%.6g Position[11]=%.6g\n",
                cycle, values["Position"][10], values["FSR"][0], values["Status"][0], values["Accelerometer"][2],
                fsr_sum, values["Gyroscope"][2], values["Accelerometer"][0], values["Accelerometer"][1],
                values["Position"][9], values["Position"][11]);
    std::fflush(stdout);

    // The answer.
    std::map<std::string, std::vector<float>> answer;
    if (mode == "limp") {
      answer["Stiffness"] = std::vector<float>(25, 0.f);
    } else if (mode == "hold") {
      if (held.empty()) held = values["Position"];
      answer["Position"] = held;
      answer["Stiffness"] = std::vector<float>(25, 1.f);
    } else {
      std::vector<float> position(25), stiffness(25, 0.5f);
      for (int i = 0; i < 25; ++i) position[i] = 0.01f * i + 0.001f * cycle;
      answer["Position"] = position;
      answer["Stiffness"] = stiffness;
    }
    msgpack::sbuffer buffer;
    msgpack::pack(buffer, answer);
    if (mode == "split") {
      const std::size_t third = buffer.size() / 3;
      writeAll(fd, buffer.data(), third);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      writeAll(fd, buffer.data() + third, third);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      writeAll(fd, buffer.data() + 2 * third, buffer.size() - 2 * third);
    } else {
      writeAll(fd, buffer.data(), buffer.size());
    }
    if (mode == "two-maps") {
      std::map<std::string, std::vector<bool>> sonar{{"Sonar", {true, false}}};
      msgpack::sbuffer second;
      msgpack::pack(second, sonar);
      writeAll(fd, second.data(), second.size());
    }
  }
  if (then_leave) {
    unsigned char packet[kPacketBytes];
    if (!readAll(fd, packet, kPacketBytes)) fail("the server closed the socket before the packet to leave");
  }
  ::close(fd);
  return 0;
}
