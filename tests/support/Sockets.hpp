// The tests' sockets (LoLA's Unix socket, the viewer's loopback HTTP, the
// GameController's UDP): connect, bind, read and write whole, listen. Not for the facts-only
// clients (lola_client, net_client, libagent_client, the probes), which
// include no project header, as a team's program would not.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace simswift::testing {

inline sockaddr_un unixAddress(const std::string& path) {
  sockaddr_un a{};
  a.sun_family = AF_UNIX;
  path.copy(a.sun_path, sizeof a.sun_path - 1);
  return a;
}

// A stream socket connected to `path`, trying `tries` times 10 ms apart
// (a server still starting); -1 if none connects.
inline int connectUnix(const std::string& path, int tries = 1) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  const sockaddr_un a = unixAddress(path);
  for (int i = 0; i < tries; ++i) {
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return fd;
    if (i + 1 < tries) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::close(fd);
  return -1;
}

// A stream socket bound at `path`, not listening (closed, it is what a
// killed server leaves: a socket file nobody serves); -1 if it cannot be bound.
inline int bindUnix(const std::string& path) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  const sockaddr_un a = unixAddress(path);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return fd;
  ::close(fd);
  return -1;
}

// A TCP socket connected to 127.0.0.1:`port`; -1 if it does not connect.
inline int connectLoopback(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) return fd;
  ::close(fd);
  return -1;
}

// Reads until `size` bytes or the end of the stream; the bytes read.
inline std::size_t readFully(int fd, void* data, std::size_t size) {
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, static_cast<char*>(data) + got, size - got);
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  return got;
}

// Everything until the other side closes.
inline std::string readToEnd(int fd) {
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::recv(fd, buf, sizeof buf, 0)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  return out;
}

// True if all of `bytes` was written.
inline bool writeAll(int fd, const std::string& bytes) {
  std::size_t put = 0;
  while (put < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + put, bytes.size() - put, MSG_NOSIGNAL);
    if (n <= 0) return false;
    put += static_cast<std::size_t>(n);
  }
  return true;
}

// A UDP socket on 127.0.0.1 at a port the kernel picks (parallel ctest runs
// never collide), read without blocking.
struct UdpListener {
  int fd = -1;
  int port = 0;
  UdpListener() {
    fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) return;
    socklen_t len = sizeof a;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
    port = ntohs(a.sin_port);
  }
  ~UdpListener() { ::close(fd); }
  UdpListener(const UdpListener&) = delete;
  UdpListener& operator=(const UdpListener&) = delete;
  // Every datagram waiting, as bytes.
  std::vector<std::vector<unsigned char>> drain() const {
    std::vector<std::vector<unsigned char>> out;
    unsigned char buf[2048];
    for (ssize_t n; (n = ::recv(fd, buf, sizeof buf, MSG_DONTWAIT)) >= 0;) out.emplace_back(buf, buf + n);
    return out;
  }
};

// One datagram to 127.0.0.1:`port`, from `fd` (-1: a socket of its own).
inline void sendUdp(int port, const void* bytes, std::size_t size, int fd = -1) {
  const int from = fd >= 0 ? fd : ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<uint16_t>(port));
  ::sendto(from, bytes, size, 0, reinterpret_cast<const sockaddr*>(&a), sizeof a);
  if (fd < 0) ::close(from);
}

}  // namespace simswift::testing
