// A behaviour played from outside the robot program: a test, a benchmark or
// a tuning tool decides what the body should do and puts the motion request
// into a mailbox (from any thread, at any time); the module sits in the
// Perception thread's behaviour slot (agent/program/ModuleOrder.cpp) and
// each camera frame writes the mailbox's latest request to the Blackboard's
// MotionRequest section, as any behaviour does. The Motion thread's standard
// MotionThreadModule takes it from there, so the walk, kicks and get-ups
// under test run through the production schedule: a request reaches Motion
// on the first Motion tick after the next camera frame (30 Hz of simulated
// time; in the simulator's lock-step 2-5 ticks after it is set between
// ticks), as a behaviour's would.
//
//   auto b = std::make_unique<agent::behaviour::RequestedBehaviour>();
//   std::shared_ptr<agent::behaviour::MotionRequestMailbox> box = b->mailbox();
//   runner.programs().setBehaviour(0, std::move(b));   // sim/programs/Programs.hpp
//   box->set([](agent::blackboard::MotionRequest& r) { r.body.type = WALK; ...; ++r.sequence; });
//
// It reads no other section: unlike the scenario's action script it does
// not stand for the game (a test field has none); the caller decides.
#pragma once

#include <memory>
#include <mutex>
#include <utility>

#include "agent/blackboard/Blackboard.hpp"
#include "agent/framework/Module.hpp"

namespace agent::behaviour {

// The latest motion request, set and read under one lock (any threads).
class MotionRequestMailbox {
 public:
  // Read-modify-write of the request: fn(blackboard::MotionRequest&). The
  // writer increments `sequence` for a new request, as a behaviour does.
  template <typename Fn>
  void set(Fn&& fn) {
    std::lock_guard<std::mutex> lock(mutex_);
    fn(request_);
  }
  blackboard::MotionRequest latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return request_;
  }

 private:
  mutable std::mutex mutex_;
  blackboard::MotionRequest request_;  // until the first set: the default (body NONE)
};

// mailbox -> motion request (each Perception step).
class RequestedBehaviour
    : public framework::ModuleOf<framework::Reads<>, framework::Writes<blackboard::MotionRequest>> {
 public:
  explicit RequestedBehaviour(std::shared_ptr<MotionRequestMailbox> mailbox = std::make_shared<MotionRequestMailbox>())
      : mailbox_(std::move(mailbox)) {}
  const char* name() const override { return "behaviour (requested)"; }
  // Shared with whoever sets the requests; outlives the program if they keep it.
  const std::shared_ptr<MotionRequestMailbox>& mailbox() const { return mailbox_; }

 private:
  void update(const In&, Out& out) override { out.get<blackboard::MotionRequest>() = mailbox_->latest(); }
  std::shared_ptr<MotionRequestMailbox> mailbox_;
};

}  // namespace agent::behaviour
