// A robot's clock page (common/clock/ClockPage.hpp) on simswift's side: the
// shared memory object it creates for a launched or external program, and
// the time it writes there each tick (ProgramDriver::publishTime, Runner
// stage 6, before the tick's sensors are posted).
#pragma once

#include <cstdint>
#include <string>

#include "common/clock/ClockPage.hpp"

namespace simswift::programs {

// The robot's view the run holds (kFlagView), for `simswift attach`.
struct PageView {
  int pid = 0;         // its init's pid; 0 = none
  std::string folder;  // the run's folder of it (absolute, < 512 bytes)
};

class ClockPage {
 public:
  using View = PageView;
  // Creates (replacing one a killed run left) the object `name`, mode 0600,
  // at t = 0 in state Starting, with `flags` (common::clock::kFlag*; with a
  // view, kFlagView too) and this process's pid. Throws std::runtime_error
  // naming it.
  ClockPage(std::string name, int64_t tick_ns, int64_t realtime_epoch_ns, uint32_t flags = 0, const View& view = {});
  ~ClockPage();  // wakes waiters (Ended), unmaps, unlinks
  ClockPage(const ClockPage&) = delete;
  ClockPage& operator=(const ClockPage&) = delete;

  const std::string& name() const { return name_; }
  // Tick `tick`'s time (tick * tick_ns), then wakes every waiter.
  void publish(int64_t tick);
  void setState(common::clock::RunState state);
  int64_t nowNs() const { return page_->now_ns.load(std::memory_order_relaxed); }

 private:
  void wake();
  std::string name_;
  common::clock::ClockLayout* page_ = nullptr;
};

}  // namespace simswift::programs
