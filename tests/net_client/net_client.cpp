// A V6 team program's network side, written only from public Linux and SPL
// facts (no simswift header): LoLA's socket /tmp/robocup (896-byte msgpack
// packets, answered with a msgpack map), the GameController's packets on
// UDP 3838 (bound to 0.0.0.0 with SO_REUSEADDR, non-blocking, as B-Human
// does; they start with "RGme"), team messages on UDP 10000 + team number,
// broadcast to 10.0.255.255 (rUNSWift's address), and a robot addressed
// 10.0.<team>.<player> on wlan0.
//
//   net-client TEAM PLAYER [SEND_TEAM]
//
// Each LoLA cycle (the N-th packet read, from 0): drains both sockets, then
// every 10th cycle (cycle % 10 == PLAYER % 10) broadcasts "p<PLAYER> c<cycle>"
// to 10000 + SEND_TEAM (default TEAM), then answers LoLA (Stiffness 0, a
// limp robot). Prints, one line each:
//   addr <wlan0's address> <its broadcast address>
//   gc <cycle> <bytes> <from address>
//   team <cycle> <from address> <payload>
//   sent <cycle>
// Exits 0 when LoLA closes the socket, 1 on a failed check, 2 on bad use.
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

[[noreturn]] void fail(const std::string& what) {
  std::printf("fail %s\n", what.c_str());
  std::fflush(stdout);
  std::exit(1);
}

int udpSocket(int port) {
  const int s = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
  const int yes = 1;
  ::setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  ::setsockopt(s, SOL_SOCKET, SO_BROADCAST, &yes, sizeof yes);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_ANY);
  a.sin_port = htons(static_cast<uint16_t>(port));
  if (::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) fail("bind " + std::to_string(port));
  return s;
}

std::string text(const sockaddr_in& a) {
  char b[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, b, sizeof b);
  return b;
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: net-client TEAM PLAYER [SEND_TEAM]\n");
    return 2;
  }
  const int team = std::atoi(argv[1]), player = std::atoi(argv[2]);
  const int send_team = argc > 3 ? std::atoi(argv[3]) : team;

  // wlan0 as B-Human and NaoTH find it: its address and broadcast address.
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) fail("getifaddrs");
  bool found = false;
  for (ifaddrs* i = list; i; i = i->ifa_next) {
    if (!i->ifa_addr || i->ifa_addr->sa_family != AF_INET || std::strcmp(i->ifa_name, "wlan0") != 0) continue;
    if (!(i->ifa_flags & IFF_BROADCAST) || !i->ifa_broadaddr) fail("wlan0 has no broadcast address");
    std::printf("addr %s %s\n", text(*reinterpret_cast<sockaddr_in*>(i->ifa_addr)).c_str(),
                text(*reinterpret_cast<sockaddr_in*>(i->ifa_broadaddr)).c_str());
    found = true;
  }
  ::freeifaddrs(list);
  if (!found) fail("no wlan0");

  const int gc = udpSocket(3838);
  const int mates = udpSocket(10000 + team);
  const int out = ::socket(AF_INET, SOCK_DGRAM, 0);
  const int yes = 1;
  ::setsockopt(out, SOL_SOCKET, SO_BROADCAST, &yes, sizeof yes);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<uint16_t>(10000 + send_team));
  ::inet_pton(AF_INET, "10.0.255.255", &to.sin_addr);

  const int lola = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, "/tmp/robocup", sizeof(address.sun_path) - 1);
  for (int tries = 0; ::connect(lola, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0; ++tries) {
    if (tries == 500) fail("cannot connect to /tmp/robocup");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  // The answer: a msgpack map {"Stiffness": [0.0 x 25]} (float32).
  std::string answer = "\x81\xa9Stiffness\xdc";
  answer += std::string("\x00\x19", 2);
  for (int i = 0; i < 25; ++i) answer += std::string("\xca\x00\x00\x00\x00", 5);

  unsigned char packet[896];
  for (int cycle = 0; readAll(lola, packet, sizeof packet); ++cycle) {
    unsigned char buf[2048];
    sockaddr_in from{};
    socklen_t len = sizeof from;
    for (ssize_t n; (n = ::recvfrom(gc, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &len)) >= 0;
         len = sizeof from) {
      if (n < 4 || std::memcmp(buf, "RGme", 4) != 0) fail("a GameController packet without RGme");
      std::printf("gc %d %zd %s\n", cycle, n, text(from).c_str());
    }
    for (ssize_t n; (n = ::recvfrom(mates, buf, sizeof buf - 1, 0, reinterpret_cast<sockaddr*>(&from), &len)) >= 0;
         len = sizeof from) {
      buf[n] = '\0';
      std::printf("team %d %s %s\n", cycle, text(from).c_str(), reinterpret_cast<char*>(buf));
    }
    if (cycle % 10 == player % 10) {
      const std::string m = "p" + std::to_string(player) + " c" + std::to_string(cycle);
      if (::sendto(out, m.data(), m.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to) !=
          static_cast<ssize_t>(m.size()))
        fail("sendto");
      std::printf("sent %d\n", cycle);
    }
    std::fflush(stdout);
    if (::write(lola, answer.data(), answer.size()) != static_cast<ssize_t>(answer.size())) break;
  }
  return 0;
}
