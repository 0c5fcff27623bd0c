// A robot's two cameras served as V4L2 devices to its launched program: the
// simulator's side of common/v4l2/DeviceBlock.hpp (the shim in the program,
// shim/V4l2Device.cpp, answers the program's calls). It owns the shared block and
// its FIFOs (made here, removed when it goes); each 30 Hz camera frame the
// Runner asks what the program wants (requests()), renders the cameras it
// streams into image(c), publishes them and waits until they were taken
// (DQBUF: the lock-step, DeviceBlock.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/libagent/CameraImages.hpp"
#include "common/v4l2/DeviceBlock.hpp"

namespace simswift::bridge {

class V4l2Devices {
 public:
  // Robot `tag`'s devices at the paths `device` (top, bottom), in the block
  // `name`: "" for one of this process ("/simswift-v4l2-p<pid>-<tag>", a
  // launched program's), or the robot's own (common::v4l2::blockName, an
  // external robot's: a killed run's is taken over). Throws BridgeError
  // naming the robot if the block or a FIFO cannot be made. Registered with
  // cleanup (Cleanup.hpp): an interrupted run leaves none of it.
  V4l2Devices(const std::string& tag, const std::array<std::string, common::v4l2::kNumCameras>& device,
              const std::string& name = "");
  ~V4l2Devices();
  V4l2Devices(const V4l2Devices&) = delete;
  V4l2Devices& operator=(const V4l2Devices&) = delete;

  // The shared-memory name the program's shim opens (its environment's
  // SIMSWIFT_V4L2).
  const std::string& blockName() const { return name_; }

  // What the program asks of camera c this frame, read once and checked:
  // publish (it streams with a buffer queued) and the size it set.
  struct Request {
    bool publish = false;
    common::libagent::ImageSize size;
  };
  // Throws BridgeError naming the robot and the field if the program wrote
  // something no shim writes (a corrupt block).
  std::array<Request, common::v4l2::kNumCameras> requests();
  // Where to render camera c's YUYV frame (kMaxImageBytes).
  uint8_t* image(int c) { return block_->camera[c].image; }
  // Camera c's frame (its image in image(c), `size`) is published: frame
  // `frame` of the run, taken at t_us (simulated).
  void publish(int c, int64_t frame, int64_t t_us, common::libagent::ImageSize size);
  // Waits (wall clock: the watchdog's slice only, never deciding what is
  // taken) up to timeout_s until every frame published was taken, or its
  // camera stopped streaming, or the program closed its cameras for good
  // (every process that had them ended). True then; false on timeout.
  bool waitTaken(double timeout_s);
  // Frames published and taken, per camera (statistics, tests).
  int64_t framesPublished(int c) const { return posted_[c]; }
  // The run has ended: a program waiting in DQBUF is woken (ENODEV).
  void shutdown();

  // The block `name` and its FIFOs unlinked, if there (a killed run's, taken
  // over by a run of its robot that serves it no cameras).
  static void remove(const std::string& name);
  // The block `name` is served by a running simulator: set up (its magic)
  // and its top camera's FIFO held open by a simulator (it holds it open
  // read-write while it lives; a killed one's has no reader). No side
  // effect on the run or its program.
  static bool served(const std::string& name);
  // `simswift clean`: every V4L2 block in /dev/shm (or those of robot
  // `tag`, if given) that no running simulator serves, removed with its
  // FIFOs. Returns the names removed.
  static std::vector<std::string> removeStale(const std::string& tag = "");

 private:
  void release();  // closes, unlinks and unmaps what was made (the destructor; a failed constructor)
  bool allTaken();
  [[noreturn]] void corrupt(int c, const std::string& what) const;

  std::string tag_, name_;
  common::v4l2::DeviceBlock* block_ = nullptr;
  int ready_[common::v4l2::kNumCameras] = {-1, -1};  // write ends (O_RDWR: never blocks, never alone)
  int taken_ = -1;                                   // read end (hang-up: the program is gone)
  std::array<int64_t, common::v4l2::kNumCameras> posted_{};  // frames published
  std::array<int64_t, common::v4l2::kNumCameras> taken_seen_{};  // frames_taken last read (checked monotonic)
  std::array<bool, common::v4l2::kNumCameras> waiting_{};    // published, not yet taken
};

}  // namespace simswift::bridge
