#include "sim/network/RobotLan.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace simswift::network {

namespace {
// The bytes a lan team message carries through TeamNetwork (opaque there):
// destination address (4), source port (2), destination port (2), payload.
constexpr size_t kMetaBytes = 8;
// A frame at most this long is read whole (Ethernet's MTU and its header, and slack).
constexpr size_t kFrameBuffer = 2048;
}  // namespace

RobotLan::~RobotLan() {
  for (const Robot& r : robots_)
    if (r.fd >= 0) close(r.fd);
}

void RobotLan::add(int endpoint, int team_number, int player, int fd) {
  robots_.push_back({endpoint, team_number, player, fd, splAddress(team_number, player)});
}

const RobotLan::Robot* RobotLan::byEndpoint(int endpoint) const {
  for (const Robot& r : robots_)
    if (r.endpoint == endpoint) return &r;
  return nullptr;
}

bool RobotLan::write(const Robot& r, const UdpDatagram& d) {
  const std::vector<uint8_t> f = buildUdpFrame(d, ip_id_++);
  if (::write(r.fd, f.data(), f.size()) == static_cast<ssize_t>(f.size())) return true;
  ++stats_.write_errors;
  return false;
}

void RobotLan::readFrames(int64_t t_us, TeamNetwork& net,
                          const std::function<void(const uint8_t*, size_t)>& game_return) {
  if (!live_) {
    live_ = true;
    for (const std::vector<uint8_t>& p : pending_) sendGameData(p);
    pending_.clear();
  }
  uint8_t frame[kFrameBuffer];
  for (const Robot& r : robots_) {
    for (int i = 0; i < kMaxFramesPerTick; ++i) {
      const ssize_t n = ::read(r.fd, frame, sizeof frame);
      if (n <= 0) break;  // EAGAIN: none left; an error (its program gone): read again next tick
      ++stats_.frames_read;
      UdpDatagram d;
      std::string why;
      if (!parseUdpFrame(frame, static_cast<size_t>(n), &d, &why)) {
        // ARP and IPv6 (router solicitations of an interface coming up) are a
        // network's ordinary traffic, not faults.
        if (why.rfind("not IPv4", 0) == 0) {
          ++stats_.dropped;
        } else {
          ++stats_.refused;
          stats_.last_refusal = why;
        }
        continue;
      }
      if (d.payload.size() > kMaxUdpPayload) {  // longer than wlan0's MTU allows: not ours to pass on
        ++stats_.refused;
        stats_.last_refusal = "a UDP payload of " + std::to_string(d.payload.size()) + " bytes";
        continue;
      }
      if (d.src_ip != r.address) {  // not from its own address: refused as spoofed
        ++stats_.refused;
        stats_.last_refusal = "from " + dotted(d.src_ip) + ", not its address " + dotted(r.address);
        continue;
      }
      if (d.dst_port == kGameReturnPort && d.dst_ip == kGameControllerAddress) {
        ++stats_.returns;
        if (game_return) game_return(d.payload.data(), d.payload.size());
        continue;
      }
      const bool team_address = d.dst_ip == kSplBroadcast || d.dst_ip == kLimitedBroadcast ||
                                (d.dst_ip & 0xffff0000u) == (kSplBroadcast & 0xffff0000u);
      if (d.dst_port == kTeamPortBase + r.team_number && team_address && d.dst_ip != r.address) {
        std::vector<uint8_t> bytes(kMetaBytes + d.payload.size());
        for (int b = 0; b < 4; ++b) bytes[b] = static_cast<uint8_t>(d.dst_ip >> (24 - 8 * b));
        bytes[4] = static_cast<uint8_t>(d.src_port >> 8), bytes[5] = static_cast<uint8_t>(d.src_port);
        bytes[6] = static_cast<uint8_t>(d.dst_port >> 8), bytes[7] = static_cast<uint8_t>(d.dst_port);
        std::memcpy(bytes.data() + kMetaBytes, d.payload.data(), d.payload.size());
        net.send(r.endpoint, bytes.data(), bytes.size(), t_us, Channel::Lan);
        ++stats_.team_sent;
        continue;
      }
      ++stats_.dropped;
    }
  }
}

bool RobotLan::deliver(const Delivery& d) {
  const Robot* to = byEndpoint(d.to);
  const Robot* from = byEndpoint(d.from);
  if (!to || !from || d.bytes.size() < kMetaBytes) return false;  // its program has no network of its own
  UdpDatagram u;
  u.dst_ip = (static_cast<uint32_t>(d.bytes[0]) << 24) | (static_cast<uint32_t>(d.bytes[1]) << 16) |
             (static_cast<uint32_t>(d.bytes[2]) << 8) | d.bytes[3];
  // A unicast reaches only the robot with that address.
  if (u.dst_ip != kSplBroadcast && u.dst_ip != kLimitedBroadcast && u.dst_ip != to->address) return false;
  u.src_ip = from->address;
  u.src_port = static_cast<uint16_t>((d.bytes[4] << 8) | d.bytes[5]);
  u.dst_port = static_cast<uint16_t>((d.bytes[6] << 8) | d.bytes[7]);
  u.payload.assign(d.bytes.begin() + kMetaBytes, d.bytes.end());
  if (!write(*to, u)) return false;
  ++stats_.team_written;
  return true;
}

void RobotLan::sendGameData(const std::vector<uint8_t>& payload) {
  if (!live_) {
    pending_.push_back(payload);
    return;
  }
  UdpDatagram u;
  u.src_ip = kGameControllerAddress;
  u.dst_ip = kSplBroadcast;
  u.src_port = kGameDataPort;
  u.dst_port = kGameDataPort;
  u.payload = payload;
  for (const Robot& r : robots_) {
    write(r, u);
    ++stats_.game_written;
  }
}

}  // namespace simswift::network
