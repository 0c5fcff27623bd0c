// A mount namespace of the calling process's own: an experiment worker's
// private /dev/shm (app/experiment/PrivateShm) and a launched LoLA program's
// /tmp/robocup (ProgramProcess) start here. When the caller is not root (or
// root may not unshare), a user namespace mapping it to itself comes first.
// Syscalls only, so a forked child may call it between fork and exec; the
// id maps are written out before the fork.
#pragma once

#include <string>

namespace simswift::programs {

// "<id> <id> 1\n" for /proc/self/uid_map and gid_map: the caller's ids.
struct IdMaps {
  char uid[32];
  char gid[32];
};
IdMaps selfIdMaps();

// Enters the namespace and makes every mount in it private (not propagated
// back to the machine). 0, or the errno of the step that failed; `step`
// (if given) names it: "unshare(user + mount namespace)", "uid_map/gid_map"
// or "mount --make-rprivate /".
int enterOwnMountNamespace(const IdMaps& maps, const char** step = nullptr);

// For a process made with clone(CLONE_NEWUSER) (ProgramProcess's init when
// simswift is not root): maps its ids to the caller's own, then enters a
// mount namespace of that user namespace (so the PID namespace it owns may
// mount its /proc) with every mount private. 0 or the errno; `step` as above.
int enterMountNamespaceInNewUser(const IdMaps& maps, const char** step = nullptr);

// Whether this machine gives a process a mount namespace of its own (no
// unprivileged user namespaces, or a container without CAP_SYS_ADMIN: no).
// Probed once per process, in a forked child that tries
// enterOwnMountNamespace. SIMSWIFT_MOUNT_NAMESPACE=off in the environment
// answers no without probing (to run as such a machine would; read at every
// call). `why` says why not ("" when available).
struct NamespaceSupport {
  bool available = false;
  std::string why;
};
NamespaceSupport mountNamespaceSupport();

// Runs `attempt` (syscalls only: 0, or an errno with `*step` naming what
// failed) in a forked child and says whether it succeeded, or why not.
// The namespace probes (mount, sim/programs/RobotNetwork's network) use it.
NamespaceSupport probeInChild(int (*attempt)(const IdMaps& maps, const char** step));


}  // namespace simswift::programs
