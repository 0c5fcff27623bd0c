#include "sim/views/FindBallRecorder.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "sim/video/VideoWriter.hpp"

namespace sim::views {

FindBallViewData viewFromInfo(const agent::blackboard::FindBallInfo& fb, int player, const std::string& tag,
                              double field_length, double field_width) {
  FindBallViewData d;
  d.field_length = field_length;
  d.field_width = field_width;
  d.columns = fb.columns;
  d.rows = fb.rows;
  d.probabilities = fb.team;
  ViewRobot self;
  self.player = player;
  self.x = fb.pose_x;
  self.y = fb.pose_y;
  self.theta = fb.pose_theta;
  self.self = true;
  self.has_target = fb.has_point;
  self.target_x = fb.point_x;
  self.target_y = fb.point_y;
  d.robots.push_back(self);
  for (const agent::blackboard::FindBallTeammate& t : fb.teammates) d.robots.push_back(viewRobot(t));
  static const char* kinds[] = {"findball2016", "findball2017", "striker"};
  const char* kind = fb.kind >= 0 && fb.kind < 3 ? kinds[fb.kind] : "?";
  char caption[128];
  std::snprintf(caption, sizeof caption, "t=%.1f s  %s  %s  %s", fb.time, tag.c_str(), kind, fb.activity);
  d.caption = caption;
  return d;
}

FindBallRecorder::FindBallRecorder(const FindBallRecorderConfig& c, std::vector<std::string> tags,
                                   std::vector<int> players)
    : c_(c), tags_(std::move(tags)), players_(std::move(players)), written_(tags_.size(), 0), view_(c.px_per_mm) {
  if (c_.rate_hz <= 0) throw std::invalid_argument("findball view rate must be > 0");
  std::filesystem::create_directories(c_.dir);
}

void FindBallRecorder::maybeCapture(int64_t t_us, const std::vector<agent::blackboard::FindBallInfo>& infos) {
  // Frame k is due at k / rate s (compared in us, so the frames do not drift).
  if (static_cast<double>(t_us) + 0.5 < static_cast<double>(next_) * 1e6 / c_.rate_hz) return;
  ++next_;
  for (size_t i = 0; i < infos.size() && i < tags_.size(); ++i) {
    if (!infos[i].active) continue;
    const std::string dir = c_.dir + "/" + tags_[i];
    if (written_[i] == 0) std::filesystem::create_directories(dir);
    char name[64];
    std::snprintf(name, sizeof name, "/findball_%06lld.png", static_cast<long long>(written_[i]));
    std::string error;
    if (!view_.writePng(viewFromInfo(infos[i], players_[i], tags_[i]), dir + name, &error))
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
