// Registry of named shared objects to unlink on exit or SIGINT/SIGTERM.
// Kept in fixed static storage so the signal handler touches no allocator.
#include <fcntl.h>
#include <semaphore.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include "sim/bridge/Cleanup.hpp"

namespace simswift::bridge::cleanup {
namespace {

constexpr int kEntries = 256;
constexpr int kNameLength = 64;

struct Entry {
  std::atomic<int> state{0};  // 0 free, 1 shm, 2 semaphore
  pid_t owner = 0;            // creator: a fork()ed child must not unlink its parent's objects
  char name[kNameLength];
};
Entry g_entries[kEntries];
std::mutex g_mutex;  // serialises register/unregister (not used by the handler)
bool g_installed = false;
struct sigaction g_old_int, g_old_term;

void unlinkAll() {
  const pid_t self = getpid();
  for (Entry& e : g_entries) {
    if (e.owner != self) continue;
    const int s = e.state.exchange(0);
    if (s == 1) shm_unlink(e.name);
    if (s == 2) sem_unlink(e.name);
  }
}

void onSignal(int sig) {
  unlinkAll();
  // Restore the previous disposition and re-raise so the exit status says
  // which signal ended the process.
  sigaction(sig, sig == SIGINT ? &g_old_int : &g_old_term, nullptr);
  raise(sig);
}

void install() {
  if (g_installed) return;
  g_installed = true;
  std::atexit(unlinkAll);
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  // A signal the process was started ignoring (e.g. SIGINT of a background
  // job) stays ignored.
  sigaction(SIGINT, nullptr, &g_old_int);
  sigaction(SIGTERM, nullptr, &g_old_term);
  if (g_old_int.sa_handler != SIG_IGN) sigaction(SIGINT, &sa, nullptr);
  if (g_old_term.sa_handler != SIG_IGN) sigaction(SIGTERM, &sa, nullptr);
}

void add(const std::string& name, int kind) {
  std::lock_guard<std::mutex> lock(g_mutex);
  install();
  for (Entry& e : g_entries) {
    if (e.state.load() == 0) {
      std::strncpy(e.name, name.c_str(), kNameLength - 1);
      e.name[kNameLength - 1] = '\0';
      e.owner = getpid();
      e.state.store(kind);
      return;
    }
  }
}

}  // namespace

void removeAll() { unlinkAll(); }

void registerShm(const std::string& name) { add(name, 1); }
void registerSem(const std::string& name) { add(name, 2); }

void unregister(const std::string& name) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (Entry& e : g_entries)
    if (e.state.load() != 0 && e.owner == getpid() && name == e.name) e.state.store(0);
}

}  // namespace simswift::bridge::cleanup
