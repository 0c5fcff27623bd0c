// A launched program's network (docs/porting.md, "Network"): a network
// namespace of its own holding loopback and `wlan0`, a TAP device with the
// robot's SPL address 10.0.<team>.<player>/16, broadcast 10.0.255.255
// (IFF_NOARP: simswift answers no ARP; every frame simswift writes goes to
// the broadcast MAC). The TAP's file descriptor goes to simswift (over a
// socketpair, SCM_RIGHTS), which then carries everything that crosses the
// robot's network (sim/network/RobotLan.hpp). A TAP (Ethernet) rather than
// a TUN device: a TUN interface is point-to-point and has no broadcast
// address, which B-Human and NaoTH read from wlan0 to send their team
// messages.
#pragma once

#include <cstdint>
#include <string>

#include "sim/programs/MountNamespace.hpp"

namespace simswift::programs {

// In ProgramProcess's init (already in its own user namespace when not
// root): unshares a network namespace, brings up lo, makes wlan0 with
// `address` (host byte order), sends its descriptor over `to_simswift` and
// closes it. Syscalls only. 0 or the errno; `step` names the step.
int enterRobotNetwork(uint32_t address, int to_simswift, const char** step = nullptr);

// simswift's side: the TAP descriptor the init sent over `from_init`
// (blocking until it comes or the init ends), non-blocking; -1 if none.
int receiveRobotNetwork(int from_init);

// Whether this machine gives a program a network namespace with a TAP
// device (/dev/net/tun usable there). Probed once per process in a forked
// child; SIMSWIFT_NETWORK_NAMESPACE=off answers no (read at every call).
NamespaceSupport robotNetworkSupport();

}  // namespace simswift::programs
