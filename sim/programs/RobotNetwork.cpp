#include "sim/programs/RobotNetwork.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <linux/if_tun.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace simswift::programs {

namespace {

void setAddress(ifreq& r, uint32_t host_order) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(host_order);
  std::memcpy(&r.ifr_addr, &a, sizeof a);
}

int up(int s, const char* name, short extra) {
  ifreq r{};
  std::strncpy(r.ifr_name, name, IFNAMSIZ - 1);
  if (ioctl(s, SIOCGIFFLAGS, &r) != 0) return errno;
  r.ifr_flags = static_cast<short>(r.ifr_flags | IFF_UP | extra);
  return ioctl(s, SIOCSIFFLAGS, &r) != 0 ? errno : 0;
}

// The TAP wlan0 in the calling process's network namespace; its fd or -errno.
int makeWlan0(int s, uint32_t address, const char** step) {
  const int tap = open("/dev/net/tun", O_RDWR | O_CLOEXEC);
  if (tap < 0) {
    if (step) *step = "open /dev/net/tun";
    return -errno;
  }
  ifreq r{};
  std::strncpy(r.ifr_name, "wlan0", IFNAMSIZ - 1);
  r.ifr_flags = IFF_TAP | IFF_NO_PI;
  if (ioctl(tap, TUNSETIFF, &r) != 0) {
    const int e = errno;
    close(tap);
    if (step) *step = "TUNSETIFF wlan0";
    return -e;
  }
  // The address first (it sets a class A mask), then the SPL's /16 and broadcast.
  const struct {
    unsigned long request;
    uint32_t value;
    const char* what;
  } steps[] = {{SIOCSIFADDR, address, "wlan0's address"},
               {SIOCSIFNETMASK, 0xffff0000u, "wlan0's netmask"},
               {SIOCSIFBRDADDR, (address & 0xffff0000u) | 0xffffu, "wlan0's broadcast address"}};
  for (const auto& st : steps) {
    ifreq a{};
    std::strncpy(a.ifr_name, "wlan0", IFNAMSIZ - 1);
    setAddress(a, st.value);
    if (ioctl(s, st.request, &a) != 0) {
      const int e = errno;
      close(tap);
      if (step) *step = st.what;
      return -e;
    }
  }
  if (const int e = up(s, "wlan0", IFF_NOARP)) {
    close(tap);
    if (step) *step = "bring wlan0 up";
    return -e;
  }
  return tap;
}

}  // namespace

int enterRobotNetwork(uint32_t address, int to_simswift, const char** step) {
  if (unshare(CLONE_NEWNET) != 0) {
    if (step) *step = "unshare(network namespace)";
    return errno;
  }
  const int s = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (s < 0) {
    if (step) *step = "socket";
    return errno;
  }
  if (const int e = up(s, "lo", 0)) {
    close(s);
    if (step) *step = "bring lo up";
    return e;
  }
  const int tap = makeWlan0(s, address, step);
  close(s);
  if (tap < 0) return -tap;
  // The descriptor to simswift (SCM_RIGHTS).
  char byte = 'w';
  iovec io{&byte, 1};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  msghdr m{};
  m.msg_iov = &io;
  m.msg_iovlen = 1;
  m.msg_control = control;
  m.msg_controllen = sizeof control;
  cmsghdr* c = CMSG_FIRSTHDR(&m);
  c->cmsg_level = SOL_SOCKET;
  c->cmsg_type = SCM_RIGHTS;
  c->cmsg_len = CMSG_LEN(sizeof(int));
  std::memcpy(CMSG_DATA(c), &tap, sizeof tap);
  ssize_t n;
  do n = sendmsg(to_simswift, &m, MSG_NOSIGNAL);
  while (n < 0 && errno == EINTR);
  const int e = n == 1 ? 0 : errno;
  close(tap);
  close(to_simswift);
  if (e && step) *step = "send wlan0 to simswift";
  return e;
}

int receiveRobotNetwork(int from_init) {
  char byte = 0;
  iovec io{&byte, 1};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  msghdr m{};
  m.msg_iov = &io;
  m.msg_iovlen = 1;
  m.msg_control = control;
  m.msg_controllen = sizeof control;
  ssize_t n;
  do n = recvmsg(from_init, &m, MSG_CMSG_CLOEXEC);
  while (n < 0 && errno == EINTR);
  if (n != 1) return -1;
  for (cmsghdr* c = CMSG_FIRSTHDR(&m); c; c = CMSG_NXTHDR(&m, c)) {
    if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_RIGHTS || c->cmsg_len != CMSG_LEN(sizeof(int))) continue;
    int fd = -1;
    std::memcpy(&fd, CMSG_DATA(c), sizeof fd);
    if (fd >= 0) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    return fd;
  }
  return -1;
}

namespace {

// The probe's attempt (in a forked child, probeInChild): a network
// namespace (in a user namespace when not root) and a wlan0 in it.
int tryRobotNetwork(const IdMaps& maps, const char** step) {
  int err = 0;
  if (geteuid() != 0 || unshare(CLONE_NEWNET) != 0) {
    // As the init does when not root: a user namespace first.
    *step = "unshare(user + network namespace)";
    if (unshare(CLONE_NEWUSER) != 0) {
      err = errno;
    } else {
      const int u = open("/proc/self/setgroups", O_WRONLY);
      if (u >= 0) (void)!write(u, "deny", 4), close(u);
      for (const auto& [path, text] : {std::pair{"/proc/self/uid_map", maps.uid}, {"/proc/self/gid_map", maps.gid}}) {
        const int f = open(path, O_WRONLY);
        if (f >= 0) (void)!write(f, text, std::strlen(text)), close(f);
      }
      if (unshare(CLONE_NEWNET) != 0) err = errno;
    }
  }
  if (err == 0) {
    const int s = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    const int tap = makeWlan0(s, 0x0A000101u, step);
    if (tap < 0) err = -tap;
  }
  return err;
}

}  // namespace

NamespaceSupport robotNetworkSupport() {
  const char* forced = std::getenv("SIMSWIFT_NETWORK_NAMESPACE");
  if (forced && std::strcmp(forced, "off") == 0) return {false, "SIMSWIFT_NETWORK_NAMESPACE=off"};
  static std::once_flag once;
  static NamespaceSupport probed;
  std::call_once(once, [] { probed = probeInChild(tryRobotNetwork); });
  return probed;
}

}  // namespace simswift::programs
