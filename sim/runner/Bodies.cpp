#include "sim/runner/Bodies.hpp"

#include <unistd.h>

#include "common/libagent/SharedNames.hpp"
#include "common/nao/NaoFacts.hpp"
#include "common/nao/Postures.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/lola/LolaBody.hpp"
#include "sim/runner/Scenario.hpp"

namespace simswift::runner {

const char* bodyInterfaceName(bridge::BodyInterface b) {
  return b == bridge::BodyInterface::Lola ? "lola" : "libagent";
}

int64_t bodyCycleUs(bridge::BodyInterface b) {
  return b == bridge::BodyInterface::Lola ? lola::kCycleUs : common::nao::kMotionTickUs;
}

common::nao::CameraLens bodyCameraLens(bridge::BodyInterface b) {
  return b == bridge::BodyInterface::Lola ? common::nao::kV6CameraLens : common::nao::kV5CameraLens;
}

std::string defaultLolaSocket(int team, int player, bool bare) {
  if (bare) return std::string(lola::kDefaultSocketPath);
  return std::string(lola::kSharedSocketFolder) + "/" + common::libagent::robotTag(team, player);
}

std::unique_ptr<bridge::BodySide> makeBody(const RobotSpec& spec, const BodyOptions& options) {
  const common::libagent::JointValues initial = common::nao::postureCommand(spec.posture);
  if (spec.body == bridge::BodyInterface::Lola) {
    lola::LolaBodyOptions lo;
    // No socket named (an experiment's trial): one of this process's own,
    // so parallel trials of the same robot never meet; in /dev/shm, which a
    // worker that launches programs makes its own (app/experiment/
    // PrivateShm.hpp), so nothing is left there after a kill -9.
    lo.socket_path = !spec.lola_socket.empty() ? spec.lola_socket
                                               : "/dev/shm/simswift-lola-p" + std::to_string(::getpid()) + "-" +
                                                     common::libagent::robotTag(spec.team, spec.player);
    lo.images = options.images;
    lo.named = options.named;
    try {
      return std::make_unique<lola::LolaBody>(spec.team, spec.player, initial, lo);
    } catch (const lola::ServerError& e) {
      throw bridge::BridgeError("robot " + common::libagent::robotTag(spec.team, spec.player) + ": " + e.what());
    }
  }
  bridge::BodyHostOptions ho;
  ho.bare_names = spec.bare_names;
  ho.release = spec.release;
  ho.start = spec.start;
  ho.images = options.images;
  return std::make_unique<bridge::BodyHost>(
      spec.team, spec.player, options.named ? bridge::BodyHost::Mode::Named : bridge::BodyHost::Mode::InProcess,
      initial, ho);
}

}  // namespace simswift::runner
