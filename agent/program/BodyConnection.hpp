// What the robot program's threads hold of the body: Motion's ticks,
// sensors and command, Perception's camera frames. Chosen at start, one of:
//   libagent  the NAO V5: the libagent block (common/libagent/AgentConnection)
//   LoLA      the NAO V6: LoLA's socket for Motion (common/lola/LolaConnection,
//             the sensors in the V5's slot layout), simswift's extension
//             object for the camera frames, game state and team link
// Everything above it (the modules, Motion's walk and kicks, Perception) is
// the same for both.
#pragma once

#include <cstdint>
#include <memory>

#include "common/libagent/AgentConnection.hpp"
#include "common/lola/LolaConnection.hpp"
#include "common/nao/NaoFacts.hpp"

namespace agent::program {

class BodyConnection {
 public:
  virtual ~BodyConnection() = default;

  // Tells the body side a program is here (`perception`: a thread will take
  // camera frames); before the first tick is answered.
  virtual void announce(bool perception) = 0;
  // Motion: the next tick (blocking / inline: one already posted). False
  // when the run is over or the body has gone.
  virtual bool waitTick() = 0;
  virtual bool takeTick() = 0;
  virtual common::libagent::SensorValues readSensors() = 0;
  // Simulated time of the sensors read, us.
  virtual int64_t timeUs() const = 0;
  virtual void writeActuators(const common::libagent::JointValues& joints, bool stiffen) = 0;
  // libagent's block (standing, buttons: LibagentIO); null for other bodies.
  virtual common::libagent::AgentConnection* libagent() { return nullptr; }

  // Perception: simswift's extension object (AgentConnection's camera side).
  virtual common::libagent::AgentConnection& camera() = 0;
  const common::libagent::AgentConnection& camera() const { return const_cast<BodyConnection*>(this)->camera(); }
  // The run is over (set by the body side), or a body attached by name has gone.
  virtual bool shutdown() const = 0;
  virtual bool simulatorAlive() const = 0;
  // The cameras' lens of the body this connection drives: libagent's block
  // is a NAO V5's, LoLA's socket a V6's (common/nao/NaoFacts.hpp).
  virtual common::nao::CameraLens cameraLens() const = 0;
};

std::unique_ptr<BodyConnection> libagentBody(common::libagent::AgentConnection connection);
// `camera`: the extension object's connection (AgentConnection::extensionOnly
// in this process).
std::unique_ptr<BodyConnection> lolaBody(common::lola::LolaConnection motion, common::libagent::AgentConnection camera);

}  // namespace agent::program
