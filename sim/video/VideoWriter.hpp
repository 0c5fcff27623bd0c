// A PNG sequence turned into an MP4 with ffmpeg, when ffmpeg is on PATH
// (libx264, or mpeg4 if libx264 is missing); otherwise the PNGs stay and
// the message says so. Used by the overview camera (sim/camera/Overview)
// and the FindBall view frames (sim/views/FindBallRecorder).
#pragma once

#include <string>

namespace simswift::video {

struct VideoResult {
  bool ok = false;          // an MP4 was written
  std::string output;       // its path (if ok)
  std::string codec;        // libx264 or mpeg4
  std::string message;      // one line for the user
};

class VideoWriter {
 public:
  static bool ffmpegOnPath();
  // pattern: printf-style PNG path (e.g. dir/overview_%06d.png) numbered from 0.
  static VideoResult assemble(const std::string& pattern, double fps, const std::string& mp4);
};

}  // namespace simswift::video
