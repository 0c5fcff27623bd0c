#include "agent/program/StandardModules.hpp"

#include <algorithm>
#include <cmath>

#include "agent/perception/PerceptionModules.hpp"

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
  if (block_) {
    const comms::GameState g = reader_.read(block_);
    blackboard::GameInfo next = info_;
    next.known = g.valid;
    if (g.valid) {
      next.state = static_cast<blackboard::GameStateId>(static_cast<int>(g.state));
      next.penalised = g.penalised;
      next.penalty_remaining = g.secs_till_unpenalised;
      next.our_kickoff = g.our_kickoff;
    }
    if (next.state != info_.state || next.penalised != info_.penalised || next.known != info_.known) ++next.changes;
    info_ = next;
  }
  board.game.write(info_);
}

void TeamReceiveModule::run(blackboard::Blackboard& board) {
  if (transport_) {
    const int64_t now_us = board.frame.read().sim_time_us;
    receiver_.update(*transport_, now_us);
    for (int p = 1; p <= comms::kSplMaxPlayers && p <= blackboard::kMaxTeammates; ++p) {
      const comms::TeammateState& t = receiver_.teammate(p);
      blackboard::TeammateReport& r = info_.mates[p];
      if (!t.heard) continue;
      const comms::SplMessage& m = t.last;
      r.valid = true;
      r.player = p;
      r.received = static_cast<double>(t.last_heard_us) * 1e-6;
      r.fallen = m.fallen;
      r.x = m.pose_x;
      r.y = m.pose_y;
      r.theta = m.pose_theta;
      // Their ball is robot-relative: through their pose onto the field.
      const double c = std::cos(m.pose_theta), s = std::sin(m.pose_theta);
      r.ball_x = m.pose_x + c * m.ball_x - s * m.ball_y;
      r.ball_y = m.pose_y + s * m.ball_x + c * m.ball_y;
      r.ball_vx = c * m.ball_vel_x - s * m.ball_vel_y;
      r.ball_vy = s * m.ball_vel_x + c * m.ball_vel_y;
      r.ball_age = m.ball_age < 0 ? 1e9 : m.ball_age;
      r.data = m.data;
    }
    info_.received = receiver_.stats().received;
    info_.malformed = receiver_.stats().malformed;
  }
  board.team.write(info_);
}

void TeamSendModule::run(blackboard::Blackboard& board) {
  if (!transport_ || player_ < 1 || player_ > comms::kSplMaxPlayers) return;
  const blackboard::LocalisationEstimate loc = board.localisation.read();
  const blackboard::BallEstimate ball = board.ball.read();
  comms::SplMessage m;
  m.fallen = perception::postureIsDown(board.motion.read().posture);
  m.pose_x = static_cast<float>(loc.pose.x);
  m.pose_y = static_cast<float>(loc.pose.y);
  m.pose_theta = static_cast<float>(loc.pose.theta);
  const bool seen = ball.valid && ball.time_since_seen < 1e8;
  m.ball_age = seen ? static_cast<float>(ball.time_since_seen) : -1.0f;
  if (seen) {
    m.ball_x = static_cast<float>(ball.rr_x);
    m.ball_y = static_cast<float>(ball.rr_y);
    m.ball_vel_x = static_cast<float>(ball.rr_vx);
    m.ball_vel_y = static_cast<float>(ball.rr_vy);
  }
  m.position_confidence = static_cast<int8_t>(std::lround(100 * std::clamp(loc.confidence, 0.0, 1.0)));
  if (with_findball_) {  // the behaviour's search state in the free data area
    const blackboard::FindBallInfo fb = board.findball.read();
    if (fb.payload.size() <= comms::kSplDataSize) m.data = fb.payload;
    if (fb.has_point) {
      m.walking_to_x = static_cast<float>(fb.point_x);
      m.walking_to_y = static_cast<float>(fb.point_y);
    }
  }
  sender_.maybeSend(*transport_, board.frame.read().sim_time_us, m);
}

}  // namespace agent::program
