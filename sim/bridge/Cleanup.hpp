// Named objects this process created, unlinked however it ends.
#pragma once

#include <string>

namespace simswift::bridge {

// Unlinks every registered named object at exit and on SIGINT/SIGTERM (then
// re-raises the signal), so an interrupted run leaves nothing in /dev/shm.
namespace cleanup {
void registerShm(const std::string& name);
void registerSem(const std::string& name);
void unregister(const std::string& name);
// Unlinks everything registered by this process now (e.g. before _exit when
// a robot thread hangs and cannot be joined).
void removeAll();
}  // namespace cleanup

}  // namespace simswift::bridge
