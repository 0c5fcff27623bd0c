#include "agent/program/StandardModules.hpp"

#include <algorithm>
#include <cmath>

#include "agent/perception/PerceptionModules.hpp"

namespace agent::program {

namespace S = common::libagent::Sensors;

void MotionThreadModule::update(const In& in, Out& out) {
  const blackboard::SensorFrame& s = in.get<blackboard::SensorFrame>();
  motion_.setRequest(in.get<blackboard::MotionRequest>());
  motion_.tick(s.values, s.sim_time_us, cmd_);
  out.get<blackboard::MotionState>() = motion_.state();
  blackboard::ActuatorRequest& a = out.get<blackboard::ActuatorRequest>();
  a.joints = cmd_;
  ++a.tick;
}

void GeneratorModule::update(const In& in, Out& out) {
  const blackboard::SensorFrame& s = in.get<blackboard::SensorFrame>();
  if (first_) {
    // Start from the measured angles, so a generator that only touches some
    // joints leaves the others where they are.
    for (int i = 0; i < common::libagent::kNumJoints; ++i) {
      cmd_.angles[i] = s.values.joints.angles[i];
      cmd_.stiffnesses[i] = 1.0f;
    }
    first_ = false;
  }
  if (gen_) gen_->tick(s.values, s.sim_time_us, cmd_);
  ++ticks_;
  blackboard::MotionState& m = out.get<blackboard::MotionState>();
  m.tick = ticks_;
  m.time = s.time;
  blackboard::ActuatorRequest& a = out.get<blackboard::ActuatorRequest>();
  a.joints = cmd_;
  a.tick = ticks_;
}

void PerceptionStepModule::update(const In& in, Out&) {
  const blackboard::FrameInfo& f = in.get<blackboard::FrameInfo>();
  frame_.sim_time_us = f.sim_time_us;
  frame_.frame_index = f.frame_index;
  frame_.num_observations = f.num_observations;
  std::copy(f.observations, f.observations + f.num_observations, frame_.observations);
  frame_.images_valid = f.images_valid ? 1 : 0;
  step_->step(frame_);
}

void GameStateModule::update(const In& in, Out& out) {
  const blackboard::GameControllerData& gc = in.get<blackboard::GameControllerData>();
  if (gc.present) {
    const comms::GameState g = reader_.read(&gc.block);
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
  out.get<blackboard::GameInfo>() = info_;
}

void TeamReceiveModule::update(const In& in, Out& out) {
  const blackboard::TeamInbox& inbox = in.get<blackboard::TeamInbox>();
  if (inbox.connected) {
    const int64_t now_us = in.get<blackboard::FrameInfo>().sim_time_us;
    receiver_.receive(inbox.packets, now_us);
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
  out.get<blackboard::TeamInfo>() = info_;
}

void TeamSendModule::update(const In& in, Out& out) {
  std::vector<std::vector<uint8_t>>& outbox = out.get<blackboard::TeamOutbox>().packets;
  outbox.clear();
  if (player_ < 1 || player_ > comms::kSplMaxPlayers) return;
  const blackboard::LocalisationEstimate& loc = in.get<blackboard::LocalisationEstimate>();
  const blackboard::BallEstimate& ball = in.get<blackboard::BallEstimate>();
  comms::SplMessage m;
  m.fallen = perception::postureIsDown(in.get<blackboard::MotionState>().posture);
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
  // The behaviour's search state (if it publishes one) in the free data area.
  const blackboard::FindBallInfo& fb = in.get<blackboard::FindBallInfo>();
  if (fb.payload.size() <= comms::kSplDataSize) m.data = fb.payload;
  if (fb.has_point) {
    m.walking_to_x = static_cast<float>(fb.point_x);
    m.walking_to_y = static_cast<float>(fb.point_y);
  }
  std::vector<uint8_t> packet = sender_.nextPacket(in.get<blackboard::FrameInfo>().sim_time_us, m);
  if (!packet.empty()) outbox.push_back(std::move(packet));
}

}  // namespace agent::program
