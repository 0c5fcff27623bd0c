// Compile-fail cases of the module contract (agent/framework/Module.hpp),
// compiled one at a time by ModuleScheduleTest.cpp with -DCASE=n: case 0
// must compile (the harness works), every other case must not.
// (.cc, not .cpp: kept out of test_agent's globbed sources.)
#include "agent/framework/Module.hpp"

namespace fw = agent::framework;
namespace bb = agent::blackboard;

#if CASE == 0
// A module as it should be: declares what it reads and writes, gets only those.
struct Tracker : fw::ModuleOf<fw::Reads<bb::FrameInfo>, fw::Writes<bb::BallEstimate>> {
  const char* name() const override { return "tracker"; }
  void update(const In& in, Out& out) override {
    out.get<bb::BallEstimate>().time_since_seen = in.get<bb::FrameInfo>().time;
  }
};
Tracker made;

#elif CASE == 1
// Deriving from the plain Module to write an undeclared section from run().
struct Rogue : fw::Module {
  const char* name() const override { return "rogue"; }
  std::vector<fw::SectionId> reads() const override { return {}; }
  std::vector<fw::SectionId> optionalReads() const override { return {}; }
  std::vector<fw::SectionId> writes() const override { return {}; }
  std::vector<fw::SectionId> usesPrevious() const override { return {}; }
  void run(bb::Blackboard& b) override { b.motion_request.write({}); }
};
Rogue made;

#elif CASE == 2
// A typed module overriding the Blackboard-taking entry point.
struct Rogue : fw::ModuleOf<fw::Reads<bb::FrameInfo>, fw::Writes<bb::BallEstimate>> {
  const char* name() const override { return "rogue"; }
  void update(const In&, Out&) override {}
  void run(bb::Blackboard& b) override { b.motion_request.write({}); }
};
Rogue made;

#elif CASE == 3
// A typed module writing a section it does not declare.
struct Rogue : fw::ModuleOf<fw::Reads<bb::FrameInfo>, fw::Writes<bb::BallEstimate>> {
  const char* name() const override { return "rogue"; }
  void update(const In&, Out& out) override { out.get<bb::MotionRequest>() = {}; }
};
Rogue made;

#elif CASE == 4
// A typed module given the Blackboard some other way, making its own outputs.
struct Rogue : fw::ModuleOf<fw::Reads<bb::FrameInfo>, fw::Writes<bb::BallEstimate>> {
  explicit Rogue(bb::Blackboard& b) : board_(b) {}
  const char* name() const override { return "rogue"; }
  void update(const In&, Out&) override {
    fw::Outputs<bb::MotionRequest> out(board_);
    out.get<bb::MotionRequest>() = {};
  }
  bb::Blackboard& board_;
};
#endif
