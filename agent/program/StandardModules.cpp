#include "agent/program/StandardModules.hpp"

namespace agent::program {

namespace S = libagent::Sensors;

void TouchModule::run(blackboard::Blackboard& board) {
  const blackboard::SensorFrame s = board.sensors.read();
  const float* v = s.values.sensors;
  blackboard::TouchState t;
  t.chest = v[S::ChestBoard_Button] > 0.5f;
  t.head_front = v[S::Head_Touch_Front] > 0.5f;
  t.head_middle = v[S::Head_Touch_Middle] > 0.5f;
  t.head_rear = v[S::Head_Touch_Rear] > 0.5f;
  t.left_bumper = v[S::LFoot_Bumper_Left] > 0.5f || v[S::LFoot_Bumper_Right] > 0.5f;
  t.right_bumper = v[S::RFoot_Bumper_Left] > 0.5f || v[S::RFoot_Bumper_Right] > 0.5f;
  if (chest_down_ && !t.chest) ++presses_;  // a press ends when the button comes up
  chest_down_ = t.chest;
  t.chest_presses = presses_;
  t.time = s.time;
  board.touch.write(t);
}

void MotionThreadModule::run(blackboard::Blackboard& board) {
  const blackboard::SensorFrame s = board.sensors.read();
  motion_.tick(s.values, s.sim_time_us, cmd_);  // publishes the Motion section itself
  board.actuators.update([&](blackboard::ActuatorRequest& a) {
    a.joints = cmd_;
    ++a.tick;
  });
}

void GeneratorModule::run(blackboard::Blackboard& board) {
  const blackboard::SensorFrame s = board.sensors.read();
  if (first_) {
    // Start from the measured angles, so a generator that only touches some
    // joints leaves the others where they are.
    for (int i = 0; i < libagent::kNumJoints; ++i) {
      cmd_.angles[i] = s.values.joints.angles[i];
      cmd_.stiffnesses[i] = 1.0f;
    }
    first_ = false;
  }
  if (gen_) gen_->tick(s.values, s.sim_time_us, cmd_);
  ++ticks_;
  board.motion.update([&](blackboard::MotionState& m) {
    m.tick = ticks_;
    m.time = s.time;
  });
  board.actuators.update([&](blackboard::ActuatorRequest& a) {
    a.joints = cmd_;
    a.tick = ticks_;
  });
}

void GameStateModule::run(blackboard::Blackboard& board) {
  blackboard::GameInfo next = info_;
  if (source_ && source_(&next)) {
    next.known = true;
    if (next.state != info_.state || next.penalised != info_.penalised) ++next.changes;
    info_ = next;
  }
  board.game.write(info_);
}

}  // namespace agent::program
