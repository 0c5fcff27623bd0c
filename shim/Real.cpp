#include "shim/Real.hpp"

#include <cstdio>
#include <cstdlib>

namespace simswift::shim {

void* nextSymbol(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (f == nullptr) {
    std::fprintf(stderr, "simswift shim: no %s after the shim (dlsym: %s)\n", name, dlerror());
    std::abort();
  }
  return f;
}

}  // namespace simswift::shim
