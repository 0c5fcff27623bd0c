#include "sim/views/FindBallRecorder.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "sim/video/VideoWriter.hpp"

namespace sim::views {

FindBallRecorder::FindBallRecorder(const FindBallRecorderConfig& c, std::vector<std::string> tags,
                                   std::vector<int> players)
    : c_(c), tags_(std::move(tags)), players_(std::move(players)), written_(tags_.size(), 0), view_(c.px_per_mm) {
  if (c_.rate_hz <= 0) throw std::invalid_argument("findball view rate must be > 0");
  std::filesystem::create_directories(c_.dir);
}

void FindBallRecorder::maybeCapture(int64_t t_us, const std::vector<std::optional<FindBallViewData>>& views) {
  // Frame k is due at k / rate s (compared in us, so the frames do not drift).
  if (static_cast<double>(t_us) + 0.5 < static_cast<double>(next_) * 1e6 / c_.rate_hz) return;
  ++next_;
  for (size_t i = 0; i < views.size() && i < tags_.size(); ++i) {
    if (!views[i]) continue;
    const std::string dir = c_.dir + "/" + tags_[i];
    if (written_[i] == 0) std::filesystem::create_directories(dir);
    char name[64];
    std::snprintf(name, sizeof name, "/findball_%06lld.png", static_cast<long long>(written_[i]));
    std::string error;
    if (!view_.writePng(*views[i], dir + name, &error))
      throw std::runtime_error("findball view: " + error);
    ++written_[i];
    ++frames_;
  }
}

std::string FindBallRecorder::finish() {
  std::string msg;
  for (size_t i = 0; i < tags_.size(); ++i) {
    if (written_[i] == 0) continue;
    const std::string pattern = c_.dir + "/" + tags_[i] + "/findball_%06d.png";
    const simswift::video::VideoResult v =
        simswift::video::VideoWriter::assemble(pattern, c_.rate_hz, c_.dir + "/" + tags_[i] + ".mp4");
    if (!msg.empty()) msg += "\n";
    msg += tags_[i] + ": " + std::to_string(written_[i]) + " FindBall view frames; " + v.message;
  }
  return msg;
}

}  // namespace sim::views
