// The vDSO: the kernel's clock_gettime, gettimeofday and time that libc
// (and any runtime that looks them up itself) call without a syscall. When
// the shim loads, each of those entry points in this process's vDSO is
// overwritten with a jump to the shim's answer (ClockCalls.hpp), so a call
// that bypasses libc still reads simulated time. The vDSO is found through
// the auxiliary vector (AT_SYSINFO_EHDR) and its symbols through its own
// ELF section headers (the image the kernel maps is a whole ELF file).
//
// Kernels that seal the vDSO (Linux 6.x with mseal'd system mappings: its
// mprotect fails with EINVAL, as on the 6.18 kernel this was written on)
// cannot be patched. There the vDSO is hidden instead: getauxval
// (AT_SYSINFO_EHDR) answers 0, so a runtime that finds the vDSO through it
// falls back to the syscall, which the seccomp filter traps (Seccomp.cpp).
// libc's own clock functions are the shim's either way (ClockCalls.cpp).
// What stays uncovered on such a kernel: code that finds the vDSO without
// getauxval (reading the auxiliary vector off its stack, as Go's runtime
// does; dlopen("linux-vdso.so.1")) and calls it (docs/shim.md). x86-64 only.
#include <elf.h>
#include <sys/auxv.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "shim/Clock.hpp"
#include "shim/ClockCalls.hpp"
#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/Target.hpp"

namespace simswift::shim {

namespace {

[[noreturn]] void refuse(const char* why) {
  std::fprintf(stderr, "simswift shim: %s: cannot patch the vDSO's clocks (%s); the program is stopped rather than "
                       "let them read the wall clock (docs/shim.md)\n", programName(), why);
  std::_Exit(70);
}

// movabs $target, %rax; jmp *%rax (12 bytes; the vDSO's functions are longer).
bool patch(uintptr_t at, const void* target) {
  unsigned char code[12] = {0x48, 0xb8};
  const auto t = reinterpret_cast<uintptr_t>(target);
  std::memcpy(code + 2, &t, sizeof t);
  code[10] = 0xff, code[11] = 0xe0;
  const long page = sysconf(_SC_PAGESIZE);
  const uintptr_t first = at & ~static_cast<uintptr_t>(page - 1);
  const size_t len = (at + sizeof code - first + page - 1) / page * page;
  if (mprotect(reinterpret_cast<void*>(first), len, PROT_READ | PROT_WRITE | PROT_EXEC) != 0) return false;
  std::memcpy(reinterpret_cast<void*>(at), code, sizeof code);
  mprotect(reinterpret_cast<void*>(first), len, PROT_READ | PROT_EXEC);
  return true;
}

bool g_hidden = false;  // the vDSO could not be patched: getauxval hides it

void patchVdso() {
  if (!clockActive()) return;
  const uintptr_t base = getauxval(AT_SYSINFO_EHDR);
  if (base == 0) return;  // no vDSO: every clock call goes through libc or a syscall (trapped)
  const auto* eh = reinterpret_cast<const Elf64_Ehdr*>(base);
  if (std::memcmp(eh->e_ident, ELFMAG, SELFMAG) != 0 || eh->e_ident[EI_CLASS] != ELFCLASS64)
    refuse("not a 64-bit ELF image");
  // The load bias: where the first PT_LOAD's p_vaddr landed.
  const auto* ph = reinterpret_cast<const Elf64_Phdr*>(base + eh->e_phoff);
  intptr_t bias = 0;
  for (int i = 0; i < eh->e_phnum; ++i)
    if (ph[i].p_type == PT_LOAD) {
      bias = static_cast<intptr_t>(base) - static_cast<intptr_t>(ph[i].p_vaddr - ph[i].p_offset);
      break;
    }
  const auto* sh = reinterpret_cast<const Elf64_Shdr*>(base + eh->e_shoff);
  int patched = 0;
  for (int i = 0; i < eh->e_shnum; ++i) {
    if (sh[i].sh_type != SHT_DYNSYM) continue;
    const auto* sym = reinterpret_cast<const Elf64_Sym*>(base + sh[i].sh_offset);
    const char* names = reinterpret_cast<const char*>(base + sh[sh[i].sh_link].sh_offset);
    const size_t count = sh[i].sh_size / sizeof(Elf64_Sym);
    for (size_t k = 0; k < count; ++k) {
      if (ELF64_ST_TYPE(sym[k].st_info) != STT_FUNC || sym[k].st_value == 0) continue;
      const char* name = names + sym[k].st_name;
      const void* target = nullptr;
      // Each name once: the plain names are aliases of the __vdso_ ones (same address).
      if (std::strcmp(name, "__vdso_clock_gettime") == 0) target = reinterpret_cast<const void*>(simswift_shim_clock_gettime);
      else if (std::strcmp(name, "__vdso_gettimeofday") == 0) target = reinterpret_cast<const void*>(simswift_shim_gettimeofday);
      else if (std::strcmp(name, "__vdso_time") == 0) target = reinterpret_cast<const void*>(simswift_shim_time);
      if (!target) continue;
      if (!patch(static_cast<uintptr_t>(bias + static_cast<intptr_t>(sym[k].st_value)), target)) {
        if (patched > 0) refuse("mprotect failed after a first entry point was patched");
        g_hidden = true;  // sealed: nothing patched, hidden instead
        return;
      }
      ++patched;
    }
  }
  if (patched == 0) refuse("no clock_gettime, gettimeofday or time found in it");
}

}  // namespace

__attribute__((constructor)) static void patchAtLoad() { patchVdso(); }

}  // namespace simswift::shim

extern "C" SIMSWIFT_SHIM_EXPORT unsigned long getauxval(unsigned long type) noexcept {
  using namespace simswift::shim;
  if (type == AT_SYSINFO_EHDR && g_hidden) {
    errno = ENOENT;  // as for an entry the vector does not have
    return 0;
  }
  return real<unsigned long (*)(unsigned long)>("getauxval")(type);
}
