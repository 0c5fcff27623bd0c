// The GameController's UDP sender and return-packet counter (see the header).
#include "sim/game/GameControllerUdp.hpp"

#include "sim/game/GameControlVersions.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "sim/game/GameControlPacket.hpp"

namespace simswift::game {

namespace {
// Return packets read per tick at most: a flood cannot stall the run.
constexpr int kMaxReadsPerTick = 256;

std::string where(const std::string& address, int port) { return address + ":" + std::to_string(port); }

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("game.udp: " + what + ": " + std::strerror(errno));
}

sockaddr_in loopback(int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<uint16_t>(port));
  return a;
}
}  // namespace

bool isLoopbackAddress(const std::string& s) {
  in_addr a{};
  if (inet_pton(AF_INET, s.c_str(), &a) != 1) return false;
  return (ntohl(a.s_addr) >> 24) == 127;
}

GameControllerUdp::GameControllerUdp(const GameUdpConfig& config)
    : config_(config), version_(spl::findPacketVersion(config.version)) {
  if (!version_)
    throw std::runtime_error("game.udp: no GameController packet version " + std::to_string(config_.version) +
                             " (simswift sends " + spl::packetVersionList() + ")");
  in_addr dest{};
  if (!isLoopbackAddress(config_.address) || inet_pton(AF_INET, config_.address.c_str(), &dest) != 1)
    throw std::runtime_error("game.udp: address " + config_.address + " is not a loopback IPv4 address");
  dest_addr_ = dest.s_addr;
  // Sender: from 127.0.0.1, so a robot's return packets (sent to the
  // packets' source address) stay on the loopback interface too.
  send_fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (send_fd_ < 0) fail("socket");
  const int yes = 1;
  setsockopt(send_fd_, SOL_SOCKET, SO_BROADCAST, &yes, sizeof yes);  // for 127.255.255.255
  sockaddr_in from = loopback(0);
  if (bind(send_fd_, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0) fail("cannot bind the sender to 127.0.0.1");
  // Return packets: non-blocking, read in stage 11 only.
  recv_fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (recv_fd_ < 0) fail("socket");
  sockaddr_in at = loopback(config_.return_port);
  if (bind(recv_fd_, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0)
    fail("cannot read return packets on " + where("127.0.0.1", config_.return_port) +
         " (another run with udp: on? give game.return_port, 0 = any free port)");
  socklen_t len = sizeof at;
  getsockname(recv_fd_, reinterpret_cast<sockaddr*>(&at), &len);
  return_port_ = ntohs(at.sin_port);
}

GameControllerUdp::~GameControllerUdp() {
  if (send_fd_ >= 0) close(send_fd_);
  if (recv_fd_ >= 0) close(recv_fd_);
}

void GameControllerUdp::update(int64_t t_us, const common::libagent::GameStateBlock& b) {
  if (t_us >= next_send_us_) {
    const std::vector<uint8_t> d =
        spl::encodeGameData(*version_, b, packet_number_++, static_cast<uint16_t>(config_.message_budget));
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_addr.s_addr = dest_addr_;
    to.sin_port = htons(static_cast<uint16_t>(config_.port));
    // Nobody listening is normal (the program may not have started): an
    // error is counted, never fatal.
    if (sendto(send_fd_, d.data(), d.size(), MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&to), sizeof to) ==
        static_cast<ssize_t>(d.size()))
      ++sent_;
    else
      ++send_errors_;
    if (also_) also_(d);
    while (next_send_us_ <= t_us) next_send_us_ += spl::kSendIntervalUs;
  }
  drainReturns();
}

void GameControllerUdp::drainReturns() {
  unsigned char buf[64];
  for (int i = 0; i < kMaxReadsPerTick; ++i) {
    const ssize_t n = recv(recv_fd_, buf, sizeof buf, MSG_DONTWAIT | MSG_TRUNC);
    if (n < 0) return;  // EAGAIN: none left (or a transient error: read again next tick)
    // MSG_TRUNC: n is the datagram's size; one larger than buf is refused by size.
    countReturn(buf, static_cast<size_t>(n));
  }
}

void GameControllerUdp::countReturn(const uint8_t* bytes, size_t size) {
  spl::Return r;
  if (!spl::decodeReturnData(*version_, bytes, size, &r)) {
    ++bad_returns_;
    return;
  }
  Returns& c = returns_[{r.team, r.player}];
  c.team = r.team;
  c.player = r.player;
  ++c.packets;
  c.alive += r.alive;
  c.penalise += r.penalise;
  c.unpenalise += r.unpenalise;
}

std::vector<GameControllerUdp::Returns> GameControllerUdp::returns() const {
  std::vector<Returns> v;
  for (const auto& [key, c] : returns_) v.push_back(c);
  return v;
}

}  // namespace simswift::game
