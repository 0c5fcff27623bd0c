#include "app/experiment/Files.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace simswift::experiment {

bool exists(const std::string& p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

void makeDir(const std::string& p) {
  if (mkdir(p.c_str(), 0755) != 0 && errno != EEXIST)
    throw BatchError("cannot create folder " + p + ": " + std::strerror(errno));
}

void makeDirs(const std::string& p) {
  for (size_t i = 1; i <= p.size(); ++i)
    if (i == p.size() || p[i] == '/') makeDir(p.substr(0, i));
}

std::string readFile(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw BatchError("cannot read " + p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeAtomic(const std::string& p, const std::string& text) {
  const std::string tmp = p + ".tmp" + std::to_string(getpid());
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw BatchError("cannot write " + tmp + ": " + std::strerror(errno));
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      close(fd);
      throw BatchError("cannot write " + tmp + ": " + std::strerror(errno));
    }
    done += static_cast<size_t>(n);
  }
  fsync(fd);
  close(fd);
  if (rename(tmp.c_str(), p.c_str()) != 0) throw BatchError("cannot rename " + tmp + ": " + std::strerror(errno));
}

std::string fileTail(const std::string& path, size_t max_chars) {
  if (!exists(path)) return "";
  std::string s = readFile(path);
  if (s.size() > max_chars) s = "..." + s.substr(s.size() - max_chars);
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

}  // namespace simswift::experiment
