#include "sim/bridge/ExtensionObject.hpp"

#include <cstring>
#include <new>

#include "sim/bridge/WaitStrategy.hpp"

namespace simswift::bridge {

namespace al = common::libagent;

void initialiseExtension(al::SimExtension& x, al::SyncMode sync, al::CameraImages* images) {
  const int32_t pid = x.simulator_pid.load();
  const uint64_t start = x.simulator_start.load();
  std::memset(static_cast<void*>(&x), 0, sizeof x);
  x.simulator_pid.store(pid);
  x.simulator_start.store(start);
  x.sync_mode.store(static_cast<int32_t>(sync));
  // pshared = 1: the other end may be another process.
  sem_init(&x.answered, 1, 0);
  sem_init(&x.camera.frame_ready, 1, 0);
  sem_init(&x.camera.perception_done, 1, 0);
  x.camera.magic = al::kExtensionMagic;
  new (&x.team) al::TeamLink();  // empty rings, magic set
  x.version = al::kExtensionVersion;
  if (images) images->magic = al::kCameraImagesMagic;
  std::atomic_thread_fence(std::memory_order_seq_cst);
  x.magic = al::kExtensionMagic;
  std::atomic_thread_fence(std::memory_order_seq_cst);
}

void destroyExtension(al::SimExtension& x) {
  sem_destroy(&x.answered);
  sem_destroy(&x.camera.frame_ready);
  sem_destroy(&x.camera.perception_done);
}

void CameraHandover::publish(const al::CameraFrame& frame) {
  x_->camera.frame = frame;
  // Release, then post: Perception loads the number (acquire) after its wait.
  x_->camera.frames_posted.store(++frames_posted_, std::memory_order_release);
  sem_post(&x_->camera.frame_ready);
}

bool CameraHandover::waitDone(double timeout_s) {
  const timespec deadline = monotonicIn(timeout_s);
  // The answer is Perception's frames_done reaching the last frame posted
  // (acquire: pairs with its release before the post); the semaphore only
  // wakes us. A post with an older number (one left behind by an answer
  // whose post came after a timed-out wait) is skipped.
  const auto done = [&] { return x_->camera.frames_done.load(std::memory_order_acquire) == frames_posted_; };
  for (;;) {
    if (!waitUntil(&x_->camera.perception_done, deadline)) return done();
    if (done()) return true;
  }
}

void CameraHandover::shutdown() {
  x_->shutdown.store(1);
  x_->camera.shutdown.store(1);
  sem_post(&x_->camera.frame_ready);
}

}  // namespace simswift::bridge
