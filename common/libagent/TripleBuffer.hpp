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

// Reader: returns the slot to read (now marked as being read), or kNoSlot
// when `latest` holds no valid slot (the parked actuators_latest, or a value
// a hostile or broken writer put there). The other process may change
// `latest` at any time, so each claim reads it once, checks that value and
// returns exactly the value it checked (never a second load). A writer that
// keeps republishing can make the re-check fail forever: after kClaimTries
// the claim gives up (kNoSlot), so a reader is never held by its writer.
constexpr int kNoSlot = -1;
constexpr int kClaimTries = 64;
inline int claimLatest(volatile uint8_t& latest, volatile uint8_t& read) {
  for (int t = 0; t < kClaimTries; ++t) {
    const uint8_t l = loadIndex(latest);
    if (!validSlot(l)) return kNoSlot;
    storeIndex(read, l);
    if (loadIndex(latest) == l) return l;
  }
  return kNoSlot;
}

// Writer: the slot to fill next (publish it with storeIndex(latest, slot)).
inline int writerSlot(const volatile uint8_t& latest, const volatile uint8_t& read) {
  return freeSlot(loadIndex(latest), loadIndex(read));
}

}  // namespace common::libagent
