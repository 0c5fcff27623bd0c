// The libagent triple-buffer rule on a pair of indices (latest, read), used
// by both sides for the sensor and the actuator buffers. One writer and one
// reader per buffer.
//
// Writer: take a slot that is neither latest nor being read, fill it,
// publish it as latest. Reader: copy latest into read, then read that slot.
//
// The reader re-checks `latest` after storing `read`: if the writer published
// in between, it may have picked the slot the reader was about to claim (it
// saw the old `read`), so the reader claims again. With sequentially
// consistent index accesses this makes the claimed slot safe from a writer
// that follows the rule until the next claim, whatever the threads' timing.
#pragma once

#include <cstdint>

#include "common/libagent/AgentShared.hpp"

namespace common::libagent {

// Reader: returns the slot to read (now marked as being read). `latest`
// must hold a valid slot.
inline int claimLatest(volatile uint8_t& latest, volatile uint8_t& read) {
  for (;;) {
    const uint8_t l = loadIndex(latest);
    storeIndex(read, l);
    if (loadIndex(latest) == l) return l;
  }
}

// Writer: the slot to fill next (publish it with storeIndex(latest, slot)).
inline int writerSlot(const volatile uint8_t& latest, const volatile uint8_t& read) {
  return freeSlot(loadIndex(latest), loadIndex(read));
}

}  // namespace common::libagent
