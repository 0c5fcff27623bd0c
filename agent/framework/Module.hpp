// The robot code's modules and their contracts (B-Human's MODULE(...
// REQUIRES / USES / PROVIDES) is the model). A module declares by type which
// Blackboard sections it reads and which it writes:
//
//   class BallTrackerModule
//       : public framework::ModuleOf<Reads<FrameInfo, VisionMeasurements>,
//                                    Writes<BallEstimate>, UsesPrevious<TeamInfo>> {
//     void update(const In& in, Out& out) override {
//       const FrameInfo& f = in.get<FrameInfo>();    // const: a declared read
//       out.get<BallEstimate>() = ...;                // mutable: a declared write
//     }
//   };
//
// and receives only const copies of what it reads and the values it writes:
// reading an undeclared section does not compile (In::get has no overload
// for it), nor does writing one. Reads<..., IfProvided<T>> reads T when some module
// writes it and its default value otherwise. The declared lists are what the
// schedule (agent/framework/ModuleSchedule.hpp) checks at start-up.
//
// That holds for every module, not by convention: ModuleOf is the only class
// that can derive from Module (its constructors are private), and ModuleOf's
// run(Blackboard&), the one entry point that sees the whole Blackboard, is
// final, so the framework hands a module only its In and Out. (A module
// given a Blackboard& some other way could still write it; none is.)
// tests/agent/framework: the static checks and the compile-fail cases.
#pragma once

#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <vector>

#include "agent/framework/Sections.hpp"

namespace agent::framework {

enum class ThreadId : int { Perception = 0, Motion = 1 };
const char* threadName(ThreadId t);

struct ModuleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class... T>
struct Reads {};
template <class... T>
struct Writes {};
template <class... T>
struct UsesPrevious {};
template <class T>
struct IfProvided {};  // inside Reads<>: an optional read

template <class R, class W, class U = UsesPrevious<>>
class ModuleOf;

// The untyped face the schedule sees. Only ModuleOf (below) derives from it.
class Module {
 public:
  virtual ~Module() = default;
  Module(const Module&) = delete;
  Module& operator=(const Module&) = delete;
  virtual const char* name() const = 0;
  virtual std::vector<SectionId> reads() const = 0;
  virtual std::vector<SectionId> optionalReads() const = 0;
  virtual std::vector<SectionId> writes() const = 0;
  // Sections read as they were at the end of the previous cycle (B-Human's
  // USES): may be provided later in the same thread; must still be provided.
  virtual std::vector<SectionId> usesPrevious() const = 0;

 private:
  // Private, so a class deriving from Module directly cannot be constructed:
  // its run() could write any section while declaring others.
  Module() = default;
  template <class R, class W, class U>
  friend class ModuleOf;
  friend class ModuleSchedule;
  // One cycle of the module's thread (a Motion tick or a camera frame).
  virtual void run(blackboard::Blackboard& board) = 0;
};

namespace detail {
template <class T>
struct Unwrap {
  using type = T;
  static constexpr bool optional = false;
};
template <class T>
struct Unwrap<IfProvided<T>> {
  using type = T;
  static constexpr bool optional = true;
};
template <class S, class... T>
constexpr bool kDeclared = (std::is_same_v<S, T> || ...);
}  // namespace detail

// What a module reads: copies taken from the Blackboard before it runs.
// Made only by ModuleOf::run, from the Blackboard.
template <class... T>
class Inputs {
 public:
  // Only for a section in the module's Reads<> or UsesPrevious<>.
  template <class S, class = std::enable_if_t<detail::kDeclared<S, T...>>>
  const S& get() const {
    return std::get<S>(values_);
  }

 private:
  template <class R, class W, class U>
  friend class ModuleOf;
  explicit Inputs(blackboard::Blackboard& b) : values_(SectionOf<T>::of(b).read()...) {}
  std::tuple<T...> values_;
};

// What a module writes: starts as the section's current value (the module
// is its only writer), published to the Blackboard after it runs.
// Made and published only by ModuleOf::run.
template <class... T>
class Outputs {
 public:
  // Only for a section in the module's Writes<>.
  template <class S, class = std::enable_if_t<detail::kDeclared<S, T...>>>
  S& get() {
    return std::get<S>(values_);
  }

 private:
  template <class R, class W, class U>
  friend class ModuleOf;
  explicit Outputs(blackboard::Blackboard& b) : values_(SectionOf<T>::of(b).read()...) {}
  void publish(blackboard::Blackboard& b) const { (SectionOf<T>::of(b).write(std::get<T>(values_)), ...); }
  std::tuple<T...> values_;
};

template <class... R, class... W, class... U>
class ModuleOf<Reads<R...>, Writes<W...>, UsesPrevious<U...>> : public Module {
 public:
  using In = Inputs<typename detail::Unwrap<R>::type..., U...>;
  using Out = Outputs<W...>;

  std::vector<SectionId> reads() const final { return idsWhere(false); }
  std::vector<SectionId> optionalReads() const final { return idsWhere(true); }
  std::vector<SectionId> writes() const final { return {SectionOf<W>::id...}; }
  std::vector<SectionId> usesPrevious() const final { return {SectionOf<U>::id...}; }

 protected:
  virtual void update(const In& in, Out& out) = 0;

 private:
  void run(blackboard::Blackboard& board) final {
    const In in(board);
    Out out(board);
    update(in, out);
    out.publish(board);
  }
  static std::vector<SectionId> idsWhere([[maybe_unused]] bool optional) {  // unused for Reads<>
    std::vector<SectionId> ids;
    ((detail::Unwrap<R>::optional == optional ? ids.push_back(SectionOf<typename detail::Unwrap<R>::type>::id)
                                              : void()),
     ...);
    return ids;
  }
};

}  // namespace agent::framework
