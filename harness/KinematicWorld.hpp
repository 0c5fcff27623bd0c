// A kinematic stand-in for the simulator, for LOGIC tests of the behaviour
// (tests/agent/behaviour, tests/views) and tools/findball_times (no physics,
// no noise): each robot's pose integrates its walk command
// exactly (after the walk's limits), the head yaw follows its command at the
// commanded speed, the ball is seen when it is within the reliable detection
// distance and inside the camera's horizontal field of view, and teammates
// exchange SearchPayloads as bytes (encoded, decoded) at the packet rate.
// The physics versions of these tests: tests/behaviour_physics.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "agent/behaviour/Behaviour.hpp"
#include "common/nao/NaoFacts.hpp"

namespace kin {

using namespace agent::behaviour;

struct Robot {
  int player = 2;
  Pose2 pose;
  double head_yaw = 0;  // rad
  std::unique_ptr<Behaviour> behaviour;
  bool penalised = false;
  // Ball memory (what a ball tracker would keep).
  bool ever_seen = false;
  bool sees = false;
  double last_seen = -1e9;
  Point2 ball_field;
  // Last packet sent.
  std::vector<uint8_t> packet;
  double packet_time = -1e9;
  BehaviourOutput last;
};

struct World {
  double dt = 1.0 / 30.0;        // s, behaviour tick (perception rate)
  double packet_period = 0.2;    // s, team packets at 5 Hz
  double detect_distance = 2500; // mm
  double hfov = common::nao::kV5CameraLens.horizontal_fov;  // rad, the V5 the thesis ran on
  double head_max_speed = 8.27;  // rad/s
  WalkLimits walk;
  Point2 ball{0, 0};
  double time = 0;
  std::vector<Robot> robots;

  Robot& add(int player, Pose2 pose, const BehaviourConfig& c) {
    Robot r;
    r.player = player;
    r.pose = pose;
    r.behaviour = std::make_unique<Behaviour>(c);
    robots.push_back(std::move(r));
    return robots.back();
  }

  bool visible(const Robot& r) const {
    const Point2 rel = toRobotFrame(r.pose, ball);
    const double d = std::hypot(rel.x, rel.y);
    return d <= detect_distance &&
           std::abs(wrapAngle(std::atan2(rel.y, rel.x) - r.head_yaw)) <= hfov / 2;
  }
  // Found as in the thesis (chapter 5): some robot sees it and is within 300 mm.
  bool found() const {
    for (const Robot& r : robots)
      if (visible(r) && distance(position(r.pose), ball) <= 300.0) return true;
    return false;
  }

  BehaviourInputs inputsFor(const Robot& r) const {
    BehaviourInputs in;
    in.time = time;
    in.player = r.player;
    in.self.pose = r.pose;
    in.walk = walk;
    in.game.penalised = r.penalised;
    in.ball.ever_seen = r.ever_seen;
    in.ball.seen_now = r.sees;
    in.ball.time_since_seen = r.ever_seen ? time - r.last_seen : 1e9;
    in.ball.field = r.ball_field;
    in.ball.relative = toRobotFrame(r.pose, r.ball_field);
    for (const Robot& o : robots) {
      if (&o == &r) continue;
      Teammate t;
      t.player = o.player;
      t.pose = o.pose;
      t.penalised = o.penalised;
      t.sees_ball = o.sees;
      t.time_since_heard = time - o.packet_time;
      if (!o.packet.empty()) {
        auto p = SearchPayload::fromBytes(o.packet);
        if (p) t.search = *p;
      }
      if (o.sees) {
        in.team_ball.valid = true;
        in.team_ball.time_since_seen = 0;
        in.team_ball.field = o.ball_field;
      }
      in.teammates.push_back(t);
    }
    return in;
  }

  // One behaviour tick for every robot, then integrate.
  void step() {
    for (Robot& r : robots) {
      r.sees = visible(r);
      if (r.sees) {
        r.ever_seen = true;
        r.last_seen = time;
        r.ball_field = ball;
      }
    }
    std::vector<BehaviourOutput> outs;
    for (Robot& r : robots) outs.push_back(r.behaviour->tick(inputsFor(r)));
    for (size_t i = 0; i < robots.size(); ++i) {
      Robot& r = robots[i];
      r.last = outs[i];
      // Every robot sends a packet (pose, ...) at the packet rate; its free
      // data carries the search payload when the behaviour has one.
      if (time - r.packet_time >= packet_period - 1e-9) {
        if (outs[i].payload) r.packet = outs[i].payload->toBytes();
        r.packet_time = time;
      }
      const auto& b = outs[i].request.body;
      if (b.type == agent::blackboard::ActionType::WALK && !r.penalised) {
        const auto c = WalkTo::clampToWalk(b, walk);
        const double ct = std::cos(r.pose.theta), st = std::sin(r.pose.theta);
        r.pose.x += (ct * c.forward - st * c.left) * dt;
        r.pose.y += (st * c.forward + ct * c.left) * dt;
        r.pose.theta = wrapAngle(r.pose.theta + c.turn * dt);
      }
      const auto& h = outs[i].request.head;
      const double step = std::min<double>(h.yaw_speed, head_max_speed) * dt;
      r.head_yaw += std::clamp(h.yaw - r.head_yaw, -step, step);
    }
    time += dt;
  }

  // Runs until found or `limit` s; returns the time taken (or limit + 1).
  double runUntilFound(double limit) {
    while (time <= limit) {
      if (found()) return time;
      step();
    }
    return limit + 1;
  }
};

}  // namespace kin
