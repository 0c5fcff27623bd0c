#include "sim/lola/LolaServer.hpp"

#include "common/lock/PidLock.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace simswift::lola {

const char* toString(Exchange::Status status) {
  switch (status) {
    case Exchange::Status::Answered: return "answered";
    case Exchange::Status::NoClient: return "no client";
    case Exchange::Status::Timeout: return "timeout";
    case Exchange::Status::Disconnected: return "disconnected";
    case Exchange::Status::ProtocolError: return "protocol error";
    case Exchange::Status::Stalled: return "stalled";
  }
  return "?";
}

namespace {

std::string sysError(const std::string& what, const std::string& path) {
  return "LoLA socket " + path + ": " + what + ": " + std::strerror(errno);
}

void setNonBlocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  fcntl(fd, F_SETFL, flags | O_NONBLOCK);
}

// Milliseconds left until `deadline`, rounded up, for poll() (0 once past it).
int msLeft(Clock::time_point deadline) {
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

// How long a new server waits for the lock beside a socket when its
// holder's pid is gone (a `simswift clean` probing it for an instant, a
// killed run's forked workers ending): s.
constexpr double kLockWait_s = 2.0;

bool peerHungUp(int fd) {
  pollfd p{fd, POLLRDHUP, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLRDHUP | POLLHUP | POLLERR)) != 0;
}

}  // namespace

void makeSocketFolder(const std::string& socket_path) {
  const std::filesystem::path parent = std::filesystem::path(socket_path).parent_path();
  if (parent.empty()) return;
  if (parent != kSharedSocketFolder) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);  // the bind then says what is wrong
    return;
  }
  const std::string dir = parent.string();
  constexpr mode_t kShared = S_ISVTX | 0777;
  // Made 0700 first and opened to everyone once it is certainly ours: the
  // mode never depends on the umask, and nobody else can have made it
  // in between (mkdir fails on an existing path).
  if (::mkdir(dir.c_str(), 0700) == 0) {
    if (::chmod(dir.c_str(), kShared) != 0) throw ServerError(sysError("chmod 01777", dir));
    return;
  }
  if (errno != EEXIST) throw ServerError(sysError("mkdir", dir));
  struct stat st{};
  if (::lstat(dir.c_str(), &st) != 0) throw ServerError(sysError("lstat", dir));
  if (!S_ISDIR(st.st_mode)) throw ServerError("LoLA sockets' folder " + dir + ": exists and is not a directory");
  if ((st.st_mode & 07777) == kShared) return;
  if (st.st_uid == ::geteuid() && ::chmod(dir.c_str(), kShared) == 0) return;
  char mode[8];
  std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
  throw ServerError("LoLA sockets' folder " + dir + ": belongs to uid " + std::to_string(st.st_uid) + " with mode " +
                    mode + ", so other users cannot make sockets in it: its owner (or root) runs `chmod 1777 " +
                    dir + "` (or removes it), or name the robot's socket in the scenario (lola: {socket: ...})");
}

std::string lockPath(const std::string& socket_path) { return socket_path + ".lock"; }

bool socketServed(const std::string& socket_path) {
  struct stat st{};
  return ::lstat(socket_path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode) &&
         common::lock::lockHeld(lockPath(socket_path));
}

std::vector<std::string> removeStaleSockets(const std::vector<std::string>& folders, const std::string& prefix) {
  std::vector<std::string> removed;
  for (const std::string& folder : folders) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
      const std::string path = entry.path().string();
      if (entry.path().filename().string().rfind(prefix, 0) != 0) continue;
      struct stat st{};
      if (lstat(path.c_str(), &st) != 0 || !S_ISSOCK(st.st_mode)) continue;
      // Its server holds the lock beside it while it lives: asked without
      // connecting, so a live run's client is never disturbed. Taken here,
      // it keeps a server starting now from binding while the file goes.
      try {
        common::lock::PidLock lock(lockPath(path));
        if (!lock.tryLock(0)) continue;
        if (::unlink(path.c_str()) == 0) removed.push_back(path);
        lock.removeAndRelease();
      } catch (const common::lock::LockError&) {
        // Not ours to judge (no access): left.
      }
    }
  }
  return removed;
}

LolaServer::LolaServer(std::string socket_path, DecoderOptions decoder)
    : path_(std::move(socket_path)), decoder_(decoder) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path_.empty() || path_.size() >= sizeof(address.sun_path))
    throw ServerError("LoLA socket \"" + path_ + "\": the path must have 1.." +
                      std::to_string(sizeof(address.sun_path) - 1) + " characters");
  std::memcpy(address.sun_path, path_.c_str(), path_.size() + 1);
  makeSocketFolder(path_);
  // The robot's socket is this server's while it holds the lock beside it
  // (common/lock/PidLock.hpp): a live server's is refused, never taken
  // over, and nobody needs to connect to find out.
  try {
    lock_ = common::lock::PidLock(lockPath(path_));
    if (!lock_.tryLock(kLockWait_s)) {
      const int pid = lock_.holderPid();
      throw ServerError("LoLA socket " + path_ + ": another server is listening there" +
                        (pid > 0 ? " (pid " + std::to_string(pid) + ")" : std::string()));
    }
  } catch (const common::lock::LockError& e) {
    throw ServerError("LoLA socket " + path_ + ": " + e.what());
  }
  struct stat st{};
  if (lstat(path_.c_str(), &st) == 0) {
    if (!S_ISSOCK(st.st_mode)) throw ServerError("LoLA socket " + path_ + ": exists and is not a socket");
    ::unlink(path_.c_str());  // a stale socket of an earlier run (nobody holds its lock)
  }
  listener_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listener_ < 0) throw ServerError(sysError("socket", path_));
  if (::bind(listener_, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0 ||
      ::listen(listener_, 4) != 0) {
    const std::string message = sysError("bind/listen", path_);
    ::close(listener_);
    throw ServerError(message);
  }
  setNonBlocking(listener_);
}

LolaServer::~LolaServer() {
  dropClient();
  if (listener_ >= 0) {
    ::close(listener_);
    ::unlink(path_.c_str());
  }
  lock_.removeAndRelease();  // after the socket: the next server finds neither
}

void LolaServer::dropClient() {
  if (client_ >= 0) ::close(client_);
  client_ = -1;
  decoder_.reset();
}

void LolaServer::adopt(int fd) {
  dropClient();
  client_ = fd;
  setNonBlocking(client_);
  ++accepted_;
}

bool LolaServer::acceptPending() {
  for (;;) {
    const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) break;  // EAGAIN: none waiting (other errors: try again next cycle)
    // Newest wins, but only a live newcomer: one that has already hung up
    // (a probe, a client that gave up) never replaces the client.
    if (peerHungUp(fd)) {
      ::close(fd);
      continue;
    }
    adopt(fd);
  }
  return connected();
}

Exchange LolaServer::exchange(const PacketBytes& packet, std::chrono::milliseconds timeout) {
  Exchange result;
  const Clock::time_point deadline = Clock::now() + timeout;
  const int before = accepted_;
  acceptPending();
  while (!connected()) {
    pollfd p{listener_, POLLIN, 0};
    const int left = msLeft(deadline);
    if (left == 0) return result;  // NoClient
    if (::poll(&p, 1, left) < 0 && errno != EINTR) return result;
    acceptPending();
  }
  result.new_client = accepted_ != before;

  // The packet goes out whole: a client reads 896 bytes per recv().
  std::size_t sent = 0;
  while (sent < packet.size()) {
    const ssize_t n = ::send(client_, packet.data() + sent, packet.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      const int left = msLeft(deadline);
      if (left > 0) {
        pollfd p{client_, POLLOUT, 0};
        ::poll(&p, 1, left);
        continue;  // send again: the rest of the packet, or the error that ended the connection
      }
      result.status = Exchange::Status::Stalled;
      result.error = "the client did not read: its socket buffer stayed full (" + std::to_string(sent) +
                     " of 896 bytes sent)";
      dropClient();
      return result;
    }
    result.status = Exchange::Status::Disconnected;  // EPIPE, ECONNRESET: the client has gone
    dropClient();
    return result;
  }

  return readAnswer(result, deadline);
}

Exchange LolaServer::awaitAnswer(std::chrono::milliseconds timeout) {
  Exchange result;
  if (!connected()) {
    result.status = Exchange::Status::Disconnected;
    return result;
  }
  return readAnswer(result, Clock::now() + timeout);
}

// Reads until the cycle's answer.
Exchange LolaServer::readAnswer(Exchange result, Clock::time_point deadline) {
  char buffer[4096];
  for (;;) {
    if (decoder_.hasAnswer()) {
      result.status = Exchange::Status::Answered;
      result.command = decoder_.takeAnswer();
      return result;
    }
    const ssize_t n = ::recv(client_, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n > 0) {
      if (!decoder_.feed(buffer, static_cast<std::size_t>(n))) {
        result.status = Exchange::Status::ProtocolError;
        result.error = decoder_.error();
        dropClient();
        return result;
      }
      continue;
    }
    if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
      result.status = Exchange::Status::Disconnected;
      dropClient();
      return result;
    }
    if (errno == EINTR) continue;
    pollfd p{client_, POLLIN, 0};
    const int left = msLeft(deadline);
    if (left == 0) {
      result.status = Exchange::Status::Timeout;
      return result;
    }
    if (::poll(&p, 1, left) < 0 && errno != EINTR) {
      result.status = Exchange::Status::Timeout;
      return result;
    }
  }
}

}  // namespace simswift::lola
