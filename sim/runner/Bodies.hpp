// The body side's factory: per robot the body interface the scenario names
// (sim/bridge/BodySide.hpp), and each interface's cycle, the robot's tick.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "common/nao/NaoFacts.hpp"
#include "sim/bridge/BodySide.hpp"

namespace simswift::runner {

struct RobotSpec;

const char* bodyInterfaceName(bridge::BodyInterface b);  // "libagent", "lola"
// us: the NAO V5's DCM cycle, 10 ms (common::nao::kMotionTickUs: libagent
// serves the robot program once per DCM cycle); LoLA's 12 ms
// (sim/lola/Protocol.hpp kCycleUs). One world runs one cycle: the scenario
// refuses robots whose cycles differ.
int64_t bodyCycleUs(bridge::BodyInterface b);
// The cameras' lens of the robot behind each interface: the V5's behind
// libagent, the V6's behind LoLA (common/nao/NaoFacts.hpp).
common::nao::CameraLens bodyCameraLens(bridge::BodyInterface b);
// The V6's LoLA socket a robot gets when the scenario names none:
// /tmp/robocup with names: bare (what an unchanged program opens), else
// /tmp/simswift-lola/t<team>p<player> (a second live run with the same robot
// is refused, as libagent's names are).
std::string defaultLolaSocket(int team, int player, bool bare);

struct BodyOptions {
  bool named = false;   // a program in another process reaches the body by name
  bool images = false;  // camera images for the program
};
// Robot `spec`'s body side, starting in `posture` (throws BridgeError,
// lola::ServerError naming the robot).
std::unique_ptr<bridge::BodySide> makeBody(const RobotSpec& spec, const BodyOptions& options);

}  // namespace simswift::runner
