#include "sim/programs/ProgramDriver.hpp"

#include "sim/bridge/BodySide.hpp"

namespace simswift::programs {

// Every program answers through its body side, wherever it runs.
bool ProgramDriver::await(Step step, double timeout_s) {
  return step == Step::Motion ? slot_.host->waitAnswer(timeout_s) : slot_.host->waitPerceptionDone(timeout_s);
}

}  // namespace simswift::programs
