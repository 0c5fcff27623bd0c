// FindBall view frames during a run (`simswift run S.yaml --findball-view DIR
// [--findball-view-rate HZ]`): at a fixed rate of simulated time, one PNG per
// robot whose behaviour publishes the Blackboard's findball section, drawn
// from that section alone (the program side's observer hook gives it) (what the robot itself believes: its pose, its
// team distribution, its search point, teammates and the points their
// packets name) -- DIR/<robot tag>/findball_<frame:06d>.png; at the end each
// robot's frames become DIR/<robot tag>.mp4 (sim/video, if ffmpeg is there).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/views/FindBallView.hpp"

namespace sim::views {

struct FindBallRecorderConfig {
  std::string dir;       // output folder (created)
  double rate_hz = 2.0;  // frames per simulated second
  double px_per_mm = 0.08;
};

class FindBallRecorder {
 public:
  // tags / players: by robot index (e.g. "t19p2", 2).
  FindBallRecorder(const FindBallRecorderConfig& c, std::vector<std::string> tags, std::vector<int> players);
  // At simulated time t_us: if a frame is due, writes one PNG per robot
  // that shows a search (views by robot index, filled by the program side's
  // observer hook, sim/programs/FindBallObserver.hpp; empty ones are
  // skipped). Throws std::runtime_error if a PNG cannot be written.
  void maybeCapture(int64_t t_us, const std::vector<std::optional<FindBallViewData>>& views);
  // Assembles the videos; one message line per robot.
  std::string finish();
  int64_t frames() const { return frames_; }  // PNGs written
  const FindBallRecorderConfig& config() const { return c_; }

 private:
  FindBallRecorderConfig c_;
  std::vector<std::string> tags_;
  std::vector<int> players_;
  std::vector<int64_t> written_;  // per robot
  int64_t next_ = 0;              // next frame index due
  int64_t frames_ = 0;
  FindBallView view_;
};

}  // namespace sim::views
