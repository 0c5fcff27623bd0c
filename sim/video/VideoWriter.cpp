#include "sim/video/VideoWriter.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace simswift::video {

namespace {
// Single-quotes a path for /bin/sh.
std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

bool VideoWriter::ffmpegOnPath() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    const std::string f = dir + "/ffmpeg";
    if (::access(f.c_str(), X_OK) == 0) return true;
  }
  return false;
}

VideoResult VideoWriter::assemble(const std::string& pattern, double fps, const std::string& mp4) {
  VideoResult r;
  if (!ffmpegOnPath()) {
    r.message = "ffmpeg not found on PATH: frames left as PNGs (" + pattern + ")";
    return r;
  }
  const std::string log = mp4 + ".log";
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  for (const char* codec : {"libx264", "mpeg4"}) {
    std::string cmd = std::string("ffmpeg -nostdin -y -loglevel error -framerate ") + rate + " -i " +
                      shellQuote(pattern) + " -c:v " + codec + " -pix_fmt yuv420p";
    if (std::string(codec) == "mpeg4") cmd += " -q:v 3";
    cmd += " " + shellQuote(mp4) + " > " + shellQuote(log) + " 2>&1";
    std::error_code ec;
    if (std::system(cmd.c_str()) == 0 && std::filesystem::file_size(mp4, ec) > 0 && !ec) {
      r.ok = true;
      r.output = mp4;
      r.codec = codec;
      r.message = "video written: " + mp4 + " (" + codec + ", " + rate + " fps)";
      return r;
    }
  }
  r.message = "ffmpeg failed (see " + log + "): frames left as PNGs (" + pattern + ")";
  return r;
}

}  // namespace simswift::video
