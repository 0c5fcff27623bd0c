// A trial's own /dev/shm. An unchanged rUNSWift 2017 program opens
// /libagent-memory<team x 11 + player>, so two workers running the same
// team and player at once would share one block. A worker that launches
// robot programs therefore first enters a mount namespace of its own (with
// a user namespace when it is not root) with a fresh tmpfs on /dev/shm: its
// programs, started from it, see only its objects, with no change to them,
// and the tmpfs goes when the last of them exits (nothing left behind,
// also after kill -9).
//
// Where the machine forbids it (no unprivileged user namespaces, a
// container without CAP_SYS_ADMIN), runBatch runs such experiments one
// trial at a time and says so.
#pragma once

#include <string>

namespace simswift::experiment {

// In a single-threaded process (a freshly forked worker): enters the private
// namespace. Empty on success, else why not.
std::string enterPrivateShm();

// Whether enterPrivateShm() works here (tried once in a forked child).
bool privateShmAvailable(std::string* why);

}  // namespace simswift::experiment
