// Ethernet II + IPv4 + UDP frames, as a robot's wlan0 (a TAP device,
// docs/porting.md "Network") carries them: built for what simswift writes
// into a robot's network, parsed and checked for what a robot's program
// writes (another process's bytes: every length and checksum is checked
// before use; anything else is refused with why).
//
// Wire formats: Ethernet II (IEEE 802.3, type 0x0800 = IPv4), IPv4 (RFC 791;
// header checksum: RFC 1071's one's-complement sum), UDP (RFC 768: checksum
// over the pseudo-header; 0 = none, allowed over IPv4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace simswift::network {

constexpr size_t kEthernetHeader = 14;
constexpr size_t kIpv4Header = 20;  // without options (what simswift writes)
constexpr size_t kUdpHeader = 8;
// The largest UDP payload simswift builds: one Ethernet MTU (1500) less the headers.
constexpr size_t kMaxUdpPayload = 1500 - kIpv4Header - kUdpHeader;

struct UdpDatagram {
  uint32_t src_ip = 0, dst_ip = 0;  // host byte order, e.g. 10.0.19.1 = 0x0A001301
  uint16_t src_port = 0, dst_port = 0;
  std::vector<uint8_t> payload;
};

// 10.0.<team>.<player> in host order.
constexpr uint32_t splAddress(int team, int player) {
  return (10u << 24) | (static_cast<uint32_t>(team & 0xff) << 8) | static_cast<uint32_t>(player & 0xff);
}
constexpr uint32_t kSplBroadcast = (10u << 24) | 0xffffu;  // 10.0.255.255
constexpr uint32_t kLimitedBroadcast = 0xffffffffu;        // 255.255.255.255
std::string dotted(uint32_t ip);

// RFC 1071's 16-bit one's-complement sum of `data`, folded, not inverted,
// starting from `sum`.
uint32_t onesSum(const uint8_t* data, size_t size, uint32_t sum = 0);

// An Ethernet frame to the broadcast MAC (ff:ff:ff:ff:ff:ff) from a fixed
// source MAC, holding `d` (payload at most kMaxUdpPayload: longer is an
// std::invalid_argument). TTL 64, DF set, both checksums filled.
std::vector<uint8_t> buildUdpFrame(const UdpDatagram& d, uint16_t ip_id);

// Parses one frame read from a robot's device. True and `*out` for an
// IPv4/UDP frame whose lengths and checksums hold and that is not a
// fragment; else false and `*why` (e.g. "not IPv4 (type 0x86dd)", "IPv4
// header checksum wrong").
bool parseUdpFrame(const uint8_t* frame, size_t size, UdpDatagram* out, std::string* why);

}  // namespace simswift::network
