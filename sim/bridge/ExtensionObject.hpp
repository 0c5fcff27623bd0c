// simswift's extension object (common/libagent/SimExtension.hpp) as the body
// side serves it: BodyHost keeps it beside the block, in this process or in
// named shared memory (also for a V6 robot: sim/lola/LolaBody keeps a
// BodyHost for it). It carries the 30 Hz camera hand-over, the game state
// and the team link; set up and handed over here, apart from the block.
#pragma once

#include <cstdint>

#include "common/libagent/CameraImages.hpp"
#include "common/libagent/SimExtension.hpp"

namespace simswift::bridge {

// Zeroes `x` after its owner header (simulator pid and start, kept) and sets
// it up: the semaphores (process-shared), the team link, the sync mode, the
// version, the images block's magic (if any); the magic last, so a program
// that sees it sees an initialised robot.
void initialiseExtension(common::libagent::SimExtension& x, common::libagent::SyncMode sync,
                         common::libagent::CameraImages* images = nullptr);
// Destroys the semaphores initialiseExtension made.
void destroyExtension(common::libagent::SimExtension& x);

// The 30 Hz camera hand-over on one extension object. Every hand-over is
// ordered by an atomic the program loads after its wait (frames_posted,
// frames_done), so ThreadSanitizer sees it and a stray post is never an answer.
class CameraHandover {
 public:
  explicit CameraHandover(common::libagent::SimExtension* x = nullptr) : x_(x) {}
  // The program has a Perception thread (it said so when it announced itself).
  bool consumer() const { return x_->camera.consumer.load() != 0; }
  void publish(const common::libagent::CameraFrame& frame);
  // Waits (wall clock, for the watchdog only) until Perception answered the
  // last frame published. False on timeout.
  bool waitDone(double timeout_s);
  // The run is over: the flags set and Perception woken.
  void shutdown();

 private:
  common::libagent::SimExtension* x_;
  int64_t frames_posted_ = 0;
};

}  // namespace simswift::bridge
