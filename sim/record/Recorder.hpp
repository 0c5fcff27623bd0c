// Records a run as MCAP (McapWriter.hpp): a TickObserver (sim/runner/
// TickObserver.hpp) the Runner calls at the end of every tick (stage 13,
// Runner.hpp), reading only what the Runner shows (the world's truth, each
// robot's sensors as published and command as latched, the game, the team
// network's traffic, a builtin program's belief through its driver's
// observer hook). Times are simulated ns since the run's start (no wall
// clock): the same run gives the same bytes. The topics: docs/recording.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/record/Json.hpp"
#include "sim/record/McapWriter.hpp"
#include "sim/runner/TickObserver.hpp"

namespace simswift::record {

struct RecordOptions {
  // Samples per simulated second of the poses (/tf), joints and sensors, in
  // (0, 1000]; one per tick at most (a 10 ms tick: 100 Hz). 30 Hz: Foxglove
  // and the viewer replay it smoothly, and it costs under a tenth of the
  // run's speed (docs/recording.md, bench/bench_record).
  static constexpr double kDefaultRateHz = 30;
  double rate_hz = kDefaultRateHz;
  bool cameras = true;   // camera images when the run renders them
};

// What the metadata names: simswift's version and the commit the build was
// configured from (CMakeLists.txt; "unknown" outside a git checkout).
const char* simswiftVersion();
const char* simswiftCommit();

// Foxglove's Log levels (foxglove.Log).
enum class LogLevel : int { Info = 2, Warning = 3, Error = 4 };

class Recorder : public runner::TickObserver {
 public:
  // Opens `path` (throws RecordError naming it if it cannot be written).
  Recorder(const std::string& path, RecordOptions options = {});
  ~Recorder() override;
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // The metadata, the channels and the scene, at t = 0 (after the
  // Runner's start; observe() does it at the first tick if not called).
  void begin(const runner::Runner& runner);
  void observe(const runner::Runner& runner, int64_t t_us) override;
  // An event only the caller knows (a test's verdict, the watchdog), on
  // /events at the last observed time. kind: the event's name (verdict,
  // watchdog, goal, ...); message "robot<i>: ..." when it is a robot's.
  void event(LogLevel level, const std::string& kind, const std::string& message, const std::string& file = "",
             int line = 0);
  // Writes the summary and closes the file (the destructor does it too, and
  // swallows its errors). Throws RecordError.
  void finish();

  const std::string& path() const { return writer_.path(); }
  uint64_t messages() const { return writer_.messageCount(); }

 private:
  struct RobotChannels {
    uint16_t joints, sensors, belief, camera_top, camera_bottom;
  };
  void writeScene(const runner::Runner& runner);
  void writeSample(const runner::Runner& runner, uint64_t t_ns);
  void writeEvents(const runner::Runner& runner, uint64_t t_ns);
  void writeTeam(const runner::Runner& runner, uint64_t t_ns);
  void writeBeliefs(const runner::Runner& runner, uint64_t t_ns);
  void writeCameras(const runner::Runner& runner, uint64_t t_ns);
  void log(uint64_t t_ns, LogLevel level, const std::string& kind, const std::string& message,
           const std::string& file = "", int line = 0);

  RecordOptions options_;
  McapWriter writer_;
  Json json_;
  bool begun_ = false;
  int64_t last_sample_ = -1;  // index of the last pose/joint/sensor sample
  int64_t last_frame_ = -1;   // the Runner's last camera frame recorded
  uint64_t last_t_ns_ = 0;
  uint16_t tf_ = 0, scene_ = 0, events_ = 0, team_sent_ = 0, team_delivered_ = 0;
  std::vector<RobotChannels> robots_;
  std::vector<std::vector<std::string>> frame_ids_;  // per robot, per link: "robot<i>/<link>"
  std::vector<std::string> tags_;  // per robot: "t19p2", as the runner's messages name it  // per robot, per link: "robot<i>/<link>"
  // What the last tick showed, to tell the events apart.
  std::vector<int> falls_, pushes_, penalties_;
  int game_state_ = -1;
};

}  // namespace simswift::record
