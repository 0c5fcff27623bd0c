#include "sim/network/UdpFrame.hpp"

#include <stdexcept>

namespace simswift::network {

namespace {

void put16(uint8_t* p, uint32_t v) {
  p[0] = static_cast<uint8_t>(v >> 8);
  p[1] = static_cast<uint8_t>(v);
}
void put32(uint8_t* p, uint32_t v) {
  put16(p, v >> 16);
  put16(p + 2, v & 0xffff);
}
uint16_t get16(const uint8_t* p) { return static_cast<uint16_t>((p[0] << 8) | p[1]); }
uint32_t get32(const uint8_t* p) { return (static_cast<uint32_t>(get16(p)) << 16) | get16(p + 2); }

uint16_t fold(uint32_t sum) {
  while (sum >> 16) sum = (sum & 0xffff) + (sum >> 16);
  return static_cast<uint16_t>(sum);
}

// The UDP checksum's pseudo-header (RFC 768): addresses, protocol 17, length.
uint32_t pseudoHeader(uint32_t src, uint32_t dst, size_t udp_length) {
  uint8_t p[12];
  put32(p, src);
  put32(p + 4, dst);
  p[8] = 0;
  p[9] = 17;
  put16(p + 10, static_cast<uint32_t>(udp_length));
  return onesSum(p, sizeof p);
}

// Locally administered, unicast: the GameController's and the network's MAC.
constexpr uint8_t kSourceMac[6] = {0x02, 0x53, 0x53, 0x57, 0x46, 0x54};

}  // namespace

std::string dotted(uint32_t ip) {
  return std::to_string(ip >> 24) + "." + std::to_string((ip >> 16) & 0xff) + "." + std::to_string((ip >> 8) & 0xff) +
         "." + std::to_string(ip & 0xff);
}

uint32_t onesSum(const uint8_t* data, size_t size, uint32_t sum) {
  for (size_t i = 0; i + 1 < size; i += 2) sum += static_cast<uint32_t>((data[i] << 8) | data[i + 1]);
  if (size % 2) sum += static_cast<uint32_t>(data[size - 1] << 8);
  return fold(sum);
}

std::vector<uint8_t> buildUdpFrame(const UdpDatagram& d, uint16_t ip_id) {
  if (d.payload.size() > kMaxUdpPayload)
    throw std::invalid_argument("UDP payload of " + std::to_string(d.payload.size()) + " bytes (at most " +
                                std::to_string(kMaxUdpPayload) + ")");
  const size_t udp_length = kUdpHeader + d.payload.size();
  std::vector<uint8_t> f(kEthernetHeader + kIpv4Header + udp_length, 0);
  uint8_t* eth = f.data();
  for (int i = 0; i < 6; ++i) eth[i] = 0xff;
  for (int i = 0; i < 6; ++i) eth[6 + i] = kSourceMac[i];
  put16(eth + 12, 0x0800);
  uint8_t* ip = eth + kEthernetHeader;
  ip[0] = 0x45;  // version 4, 5 words
  put16(ip + 2, static_cast<uint32_t>(kIpv4Header + udp_length));
  put16(ip + 4, ip_id);
  put16(ip + 6, 0x4000);  // don't fragment
  ip[8] = 64;             // TTL
  ip[9] = 17;             // UDP
  put32(ip + 12, d.src_ip);
  put32(ip + 16, d.dst_ip);
  put16(ip + 10, static_cast<uint16_t>(~onesSum(ip, kIpv4Header)));
  uint8_t* udp = ip + kIpv4Header;
  put16(udp, d.src_port);
  put16(udp + 2, d.dst_port);
  put16(udp + 4, static_cast<uint32_t>(udp_length));
  for (size_t i = 0; i < d.payload.size(); ++i) udp[kUdpHeader + i] = d.payload[i];
  uint16_t sum = static_cast<uint16_t>(~onesSum(udp, udp_length, pseudoHeader(d.src_ip, d.dst_ip, udp_length)));
  put16(udp + 6, sum == 0 ? 0xffff : sum);  // a computed 0 is sent as all ones (RFC 768)
  return f;
}

bool parseUdpFrame(const uint8_t* frame, size_t size, UdpDatagram* out, std::string* why) {
  auto refuse = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (size < kEthernetHeader) return refuse("shorter than an Ethernet header (" + std::to_string(size) + " bytes)");
  const uint16_t type = get16(frame + 12);
  if (type != 0x0800) {
    char hex[8];
    static const char* digits = "0123456789abcdef";
    for (int i = 0; i < 4; ++i) hex[i] = digits[(type >> (12 - 4 * i)) & 0xf];
    hex[4] = '\0';
    return refuse(std::string("not IPv4 (type 0x") + hex + ")");
  }
  const uint8_t* ip = frame + kEthernetHeader;
  const size_t avail = size - kEthernetHeader;
  if (avail < kIpv4Header) return refuse("IPv4 header cut short");
  if ((ip[0] >> 4) != 4) return refuse("IP version " + std::to_string(ip[0] >> 4));
  const size_t ihl = static_cast<size_t>(ip[0] & 0xf) * 4;
  if (ihl < kIpv4Header || ihl > avail) return refuse("IPv4 header length " + std::to_string(ihl));
  const size_t total = get16(ip + 2);
  if (total < ihl || total > avail) return refuse("IPv4 total length " + std::to_string(total) + " of " +
                                                  std::to_string(avail) + " bytes");
  if (fold(onesSum(ip, ihl)) != 0xffff) return refuse("IPv4 header checksum wrong");
  if ((get16(ip + 6) & 0x3fff) != 0) return refuse("an IPv4 fragment");
  if (ip[9] != 17) return refuse("not UDP (protocol " + std::to_string(ip[9]) + ")");
  const uint8_t* udp = ip + ihl;
  const size_t udp_avail = total - ihl;
  if (udp_avail < kUdpHeader) return refuse("UDP header cut short");
  const size_t udp_length = get16(udp + 4);
  if (udp_length < kUdpHeader || udp_length > udp_avail) return refuse("UDP length " + std::to_string(udp_length));
  const uint32_t src = get32(ip + 12), dst = get32(ip + 16);
  if (get16(udp + 6) != 0 && fold(onesSum(udp, udp_length, pseudoHeader(src, dst, udp_length))) != 0xffff)
    return refuse("UDP checksum wrong");
  out->src_ip = src;
  out->dst_ip = dst;
  out->src_port = get16(udp);
  out->dst_port = get16(udp + 2);
  out->payload.assign(udp + kUdpHeader, udp + udp_length);
  return true;
}

}  // namespace simswift::network
