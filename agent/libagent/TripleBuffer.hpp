// The libagent triple-buffer rule on a pair of indices (latest, read), used
// identically by both sides for the sensor and the actuator buffers. One
// writer and one reader per buffer.
//
// Writer: take the slot that is neither latest nor being read, fill it,
// publish it as latest. Reader: copy latest into read, then read that slot.
//
// The reader re-checks `latest` after storing `read`: if the writer published
// in between, it may have picked the slot the reader was about to claim (it
// saw the old `read`), so the reader claims again. With sequentially
// consistent atomics this makes the claimed slot safe from the writer until
// the next claim, whatever the threads' timing.
#pragma once

#include <atomic>
#include <cstdint>

#include "agent/libagent/AgentShared.hpp"

namespace agent::libagent {

// Reader: returns the slot to read (now marked as being read).
inline int claimLatest(std::atomic<int32_t>& latest, std::atomic<int32_t>& read) {
  for (;;) {
    const int32_t l = latest.load();
    read.store(l);
    if (latest.load() == l) return l;
  }
}

// Writer: the slot to fill next (publish it with latest.store(slot)).
inline int writerSlot(const std::atomic<int32_t>& latest, const std::atomic<int32_t>& read) {
  return freeSlot(latest.load(), read.load());
}

}  // namespace agent::libagent
