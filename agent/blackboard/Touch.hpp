// Buttons and bumpers, debounced by the touch module in the Motion thread.
#pragma once

#include <cstdint>

namespace agent::blackboard {

struct TouchState {
  bool chest = false, head_front = false, head_middle = false, head_rear = false;
  bool left_bumper = false, right_bumper = false;
  int32_t chest_presses = 0;  // completed presses (down then up) since start
  double time = 0;            // s
};

}  // namespace agent::blackboard
