#include "sim/programs/ClockPage.hpp"

#include <fcntl.h>
#include <linux/futex.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <new>
#include <stdexcept>

namespace simswift::programs {

namespace cc = common::clock;

ClockPage::ClockPage(std::string name, int64_t tick_ns, int64_t realtime_epoch_ns, uint32_t flags, const View& view)
    : name_(std::move(name)) {
  if (view.pid > 0 && view.folder.size() >= sizeof(cc::ClockLayout::view_folder))
    throw std::runtime_error("clock page " + name_ + ": the robot's view folder " + view.folder + " is longer than " +
                             std::to_string(sizeof(cc::ClockLayout::view_folder) - 1) +
                             " bytes (give program_logs a shorter path)");
  shm_unlink(name_.c_str());  // a killed run's page: this run's robot takes its name over
  const int fd = shm_open(name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw std::runtime_error("clock page " + name_ + ": shm_open: " + std::strerror(errno));
  if (ftruncate(fd, sizeof(cc::ClockLayout)) != 0) {
    const int e = errno;
    close(fd);
    shm_unlink(name_.c_str());
    throw std::runtime_error("clock page " + name_ + ": ftruncate: " + std::strerror(e));
  }
  void* p = mmap(nullptr, sizeof(cc::ClockLayout), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  const int e = errno;
  close(fd);
  if (p == MAP_FAILED) {
    shm_unlink(name_.c_str());
    throw std::runtime_error("clock page " + name_ + ": mmap: " + std::strerror(e));
  }
  page_ = new (p) cc::ClockLayout{};
  page_->tick_ns = tick_ns;
  page_->realtime_epoch_ns = realtime_epoch_ns;
  page_->size = sizeof(cc::ClockLayout);
  page_->flags = flags | (view.pid > 0 ? cc::kFlagView : 0u);
  page_->run_pid = static_cast<int32_t>(getpid());
  if (view.pid > 0) {
    page_->view_pid = view.pid;
    std::memcpy(page_->view_folder, view.folder.c_str(), view.folder.size() + 1);
  }
  page_->version = cc::kVersion;
  page_->now_ns.store(0, std::memory_order_relaxed);
  page_->state.store(static_cast<uint32_t>(cc::RunState::Starting), std::memory_order_relaxed);
  page_->generation.store(0, std::memory_order_relaxed);
  std::atomic_thread_fence(std::memory_order_release);
  page_->magic = cc::kMagic;  // last: a reader that sees the magic sees the header
}

ClockPage::~ClockPage() {
  if (!page_) return;
  setState(cc::RunState::Ended);
  munmap(page_, sizeof(cc::ClockLayout));
  shm_unlink(name_.c_str());
}

void ClockPage::wake() {
  page_->generation.fetch_add(1, std::memory_order_release);
  // Not FUTEX_PRIVATE: the waiters are in another process.
  syscall(SYS_futex, reinterpret_cast<uint32_t*>(&page_->generation), FUTEX_WAKE, INT_MAX, nullptr, nullptr, 0);
}

void ClockPage::publish(int64_t tick) {
  page_->now_ns.store(tick * page_->tick_ns, std::memory_order_release);
  wake();
}

void ClockPage::setState(cc::RunState state) {
  page_->state.store(static_cast<uint32_t>(state), std::memory_order_release);
  wake();
}

}  // namespace simswift::programs
