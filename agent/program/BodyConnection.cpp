#include "agent/program/BodyConnection.hpp"

namespace agent::program {

namespace {

class LibagentBody final : public BodyConnection {
 public:
  explicit LibagentBody(common::libagent::AgentConnection c) : c_(std::move(c)) {}
  void announce(bool perception) override { c_.announce(perception); }
  bool waitTick() override { return c_.waitTick(); }
  bool takeTick() override { return c_.takeTick(); }
  common::libagent::SensorValues readSensors() override { return c_.readSensors(); }
  int64_t timeUs() const override { return c_.simTimeUs(); }
  void writeActuators(const common::libagent::JointValues& joints, bool stiffen) override {
    c_.writeActuators(joints, nullptr, 0, stiffen);
  }
  common::libagent::AgentConnection* libagent() override { return &c_; }
  common::libagent::AgentConnection& camera() override { return c_; }
  bool shutdown() const override { return c_.shutdown(); }
  bool simulatorAlive() const override { return c_.simulatorAlive(); }
  common::nao::CameraLens cameraLens() const override { return common::nao::kV5CameraLens; }

 private:
  common::libagent::AgentConnection c_;
};

class LolaBody final : public BodyConnection {
 public:
  LolaBody(common::lola::LolaConnection motion, common::libagent::AgentConnection camera)
      : motion_(std::move(motion)), camera_(std::move(camera)) {}
  void announce(bool perception) override { camera_.announce(perception); }
  bool waitTick() override { return motion_.waitTick(); }
  bool takeTick() override { return motion_.takeTick(); }
  common::libagent::SensorValues readSensors() override { return motion_.readSensors(); }
  int64_t timeUs() const override { return motion_.timeUs(); }
  // LoLA has no STIFFEN: a program that wants stiffness sends it.
  void writeActuators(const common::libagent::JointValues& joints, bool /*stiffen*/) override {
    motion_.writeActuators(joints);
  }
  common::libagent::AgentConnection& camera() override { return camera_; }
  // The run's end is the extension object's flag (set before the socket
  // closes); a killed simulator only closes the socket: its pid tells.
  bool shutdown() const override { return camera_.shutdown(); }
  bool simulatorAlive() const override { return camera_.simulatorAlive(); }
  common::nao::CameraLens cameraLens() const override { return common::nao::kV6CameraLens; }

 private:
  common::lola::LolaConnection motion_;
  common::libagent::AgentConnection camera_;
};

}  // namespace

std::unique_ptr<BodyConnection> libagentBody(common::libagent::AgentConnection connection) {
  return std::make_unique<LibagentBody>(std::move(connection));
}

std::unique_ptr<BodyConnection> lolaBody(common::lola::LolaConnection motion, common::libagent::AgentConnection camera) {
  return std::make_unique<LolaBody>(std::move(motion), std::move(camera));
}

}  // namespace agent::program
