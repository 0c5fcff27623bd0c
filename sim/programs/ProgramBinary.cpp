#include "sim/programs/ProgramBinary.hpp"

#include <elf.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace simswift::programs {

std::string findExecutable(const std::string& command) {
  if (command.find('/') != std::string::npos) return access(command.c_str(), X_OK) == 0 ? command : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string p = (dir.empty() ? "." : dir) + "/" + command;
    if (access(p.c_str(), X_OK) == 0) return p;
  }
  return "";
}

std::string shimRefusal(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";  // exec reports it
  Elf64_Ehdr eh{};
  in.read(reinterpret_cast<char*>(&eh), sizeof eh);
  if (in.gcount() >= 2 && reinterpret_cast<const char*>(&eh)[0] == '#' && reinterpret_cast<const char*>(&eh)[1] == '!')
    return "";
  if (in.gcount() != sizeof eh || std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) return "";  // exec decides
  if (eh.e_ident[EI_CLASS] != ELFCLASS64)
    return "a 32-bit executable (the shim, docs/shim.md, is built for this machine's 64-bit programs)";
  if (eh.e_phentsize != sizeof(Elf64_Phdr) || eh.e_phnum == 0 || eh.e_phnum > 4096)
    return "an ELF executable whose program headers cannot be read";
  for (int i = 0; i < eh.e_phnum; ++i) {
    Elf64_Phdr ph{};
    in.seekg(static_cast<std::streamoff>(eh.e_phoff + static_cast<uint64_t>(i) * sizeof ph));
    in.read(reinterpret_cast<char*>(&ph), sizeof ph);
    if (in.gcount() != sizeof ph) return "an ELF executable whose program headers cannot be read";
    if (ph.p_type == PT_INTERP) return "";
  }
  return "a statically linked executable (no PT_INTERP): simswift's shim (docs/shim.md) cannot be preloaded into "
         "it, so it would read the machine's wall clock instead of the run's simulated time; link it dynamically";
}

}  // namespace simswift::programs
