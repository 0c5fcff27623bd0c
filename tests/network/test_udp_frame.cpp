// Ethernet + IPv4 + UDP frames (sim/network/UdpFrame.hpp): the checksums
// against published values, a round trip, and every malformed frame refused
// with why.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/network/UdpFrame.hpp"

using namespace simswift::network;

// The IPv4 header of Wikipedia's "Internet checksum" example (IPv4 header
// checksum article): 4500 0073 0000 4000 4011 0000 c0a8 0001 c0a8 00c7,
// whose checksum is 0xb861.
TEST(UdpFrame, TheIpv4HeaderChecksumOfThePublishedExample) {
  const uint8_t h[20] = {0x45, 0x00, 0x00, 0x73, 0x00, 0x00, 0x40, 0x00, 0x40, 0x11,
                         0x00, 0x00, 0xc0, 0xa8, 0x00, 0x01, 0xc0, 0xa8, 0x00, 0xc7};
  EXPECT_EQ(static_cast<uint16_t>(~onesSum(h, sizeof h)), 0xb861);
}

TEST(UdpFrame, RoundTripAndEveryMalformedFrameIsRefused) {
  UdpDatagram d;
  d.src_ip = splAddress(19, 1);
  d.dst_ip = kSplBroadcast;
  d.src_port = 40000;
  d.dst_port = 10019;
  d.payload = {'h', 'e', 'l', 'l', 'o'};  // odd length: the checksum's padding
  const std::vector<uint8_t> f = buildUdpFrame(d, 7);
  ASSERT_EQ(f.size(), 14u + 20u + 8u + 5u);
  EXPECT_EQ(dotted(d.src_ip), "10.0.19.1");
  UdpDatagram back;
  std::string why;
  ASSERT_TRUE(parseUdpFrame(f.data(), f.size(), &back, &why)) << why;
  EXPECT_EQ(back.src_ip, d.src_ip);
  EXPECT_EQ(back.dst_ip, d.dst_ip);
  EXPECT_EQ(back.src_port, d.src_port);
  EXPECT_EQ(back.dst_port, d.dst_port);
  EXPECT_EQ(back.payload, d.payload);
  // Padding after the datagram (Ethernet's minimum frame) is not payload.
  std::vector<uint8_t> padded = f;
  padded.resize(60, 0);
  ASSERT_TRUE(parseUdpFrame(padded.data(), padded.size(), &back, &why)) << why;
  EXPECT_EQ(back.payload, d.payload);

  auto refused = [&](std::vector<uint8_t> g) {
    UdpDatagram x;
    std::string w;
    EXPECT_FALSE(parseUdpFrame(g.data(), g.size(), &x, &w));
    return w;
  };
  std::vector<uint8_t> g = f;
  g[14 + 8] ^= 1;  // TTL
  EXPECT_EQ(refused(g), "IPv4 header checksum wrong");
  g = f;
  g.back() ^= 1;
  EXPECT_EQ(refused(g), "UDP checksum wrong");
  g = f;
  g[12] = 0x86, g[13] = 0xdd;
  EXPECT_EQ(refused(g), "not IPv4 (type 0x86dd)");
  EXPECT_EQ(refused(std::vector<uint8_t>(f.begin(), f.begin() + 20)), "IPv4 header cut short");
  EXPECT_EQ(refused(std::vector<uint8_t>(f.begin(), f.end() - 1)).rfind("IPv4 total length", 0), 0u);
  EXPECT_EQ(refused(std::vector<uint8_t>(f.begin(), f.begin() + 5)).rfind("shorter than", 0), 0u);
  // A fragment, and TCP, each with a correct header checksum.
  auto reChecksum = [](std::vector<uint8_t>& h) {
    h[24] = h[25] = 0;
    const uint16_t s = static_cast<uint16_t>(~onesSum(h.data() + 14, 20));
    h[24] = static_cast<uint8_t>(s >> 8), h[25] = static_cast<uint8_t>(s);
  };
  g = f;
  g[20] = 0x20;  // more fragments
  reChecksum(g);
  EXPECT_EQ(refused(g), "an IPv4 fragment");
  g = f;
  g[23] = 6;
  reChecksum(g);
  EXPECT_EQ(refused(g), "not UDP (protocol 6)");
  g = f;
  g[14 + 20 + 4] = 0xff;  // UDP length beyond the datagram
  EXPECT_EQ(refused(g).rfind("UDP length", 0), 0u);
  // A UDP checksum of 0 means none (IPv4).
  g = f;
  g[14 + 20 + 6] = g[14 + 20 + 7] = 0;
  EXPECT_TRUE(parseUdpFrame(g.data(), g.size(), &back, &why)) << why;
  // Too long a payload is refused when building, never written.
  UdpDatagram big = d;
  big.payload.assign(kMaxUdpPayload + 1, 0);
  EXPECT_THROW(buildUdpFrame(big, 0), std::invalid_argument);
}
