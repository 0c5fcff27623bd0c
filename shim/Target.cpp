#include "shim/Target.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include "common/clock/ClockPage.hpp"

namespace simswift::shim {

namespace {

char g_name[256];

const char* readName() {
  char path[4096];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return "?";
  path[n] = '\0';
  const char* slash = std::strrchr(path, '/');
  // A file name is at most NAME_MAX (255) bytes: it fits with its NUL.
  const char* base = slash ? slash + 1 : path;
  const size_t len = strnlen(base, sizeof g_name - 1);
  std::memcpy(g_name, base, len);
  g_name[len] = '\0';
  return g_name;
}

bool listed(const char* name, const char* list) {
  const size_t len = std::strlen(name);
  for (const char* p = list; p && *p;) {
    const char* end = std::strchr(p, ':');
    const size_t n = end ? static_cast<size_t>(end - p) : std::strlen(p);
    if (n == len && std::strncmp(p, name, n) == 0) return true;
    p = end ? end + 1 : nullptr;
  }
  return false;
}

bool decide() {
  const char* page = std::getenv(common::clock::kPageEnv);
  if (!page || !*page) return false;
  const char* name = programName();
  static const char* const kTools[] = {"gdb", "gdbserver", "gdb-multiarch", "lldb", "lldb-server", "strace", "ltrace"};
  for (const char* t : kTools)
    if (std::strcmp(name, t) == 0) return false;
  return !listed(name, std::getenv(common::clock::kInertEnv));
}

}  // namespace

const char* programName() {
  static const char* name = readName();
  return name;
}

bool shimActive() {
  static const bool active = decide();
  return active;
}

}  // namespace simswift::shim
