#include "common/lola/LolaConnection.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include <msgpack.hpp>

#include "common/libagent/Inertial.hpp"
#include "common/lola/Float32.hpp"
#include "common/lola/Slots.hpp"

namespace common::lola {

namespace S = libagent::Sensors;

namespace {

// The numbers of one key's array; LolaError if the value is not an array of
// `length` numbers.
std::vector<float> numbers(const msgpack::object& v, const std::string& key, std::size_t length) {
  if (v.type != msgpack::type::ARRAY || v.via.array.size != length)
    throw LolaError("LoLA sensor packet: " + key + " is not an array of " + std::to_string(length));
  std::vector<float> out(length);
  for (std::size_t i = 0; i < length; ++i) {
    const msgpack::object& e = v.via.array.ptr[i];
    switch (e.type) {
      case msgpack::type::FLOAT32:
      case msgpack::type::FLOAT64: out[i] = static_cast<float>(e.via.f64); break;
      case msgpack::type::POSITIVE_INTEGER: out[i] = static_cast<float>(e.via.u64); break;
      case msgpack::type::NEGATIVE_INTEGER: out[i] = static_cast<float>(e.via.i64); break;
      default: throw LolaError("LoLA sensor packet: " + key + "[" + std::to_string(i) + "] is not a number");
    }
  }
  return out;
}

}  // namespace

libagent::SensorValues sensorValuesFromPacket(const std::uint8_t* data, std::size_t size) {
  msgpack::object_handle handle;
  try {
    handle = msgpack::unpack(reinterpret_cast<const char*>(data), size);
  } catch (const std::exception& e) {
    throw LolaError(std::string("LoLA sensor packet: not msgpack (") + e.what() + ")");
  }
  const msgpack::object& map = handle.get();
  if (map.type != msgpack::type::MAP) throw LolaError("LoLA sensor packet: not a map");
  libagent::SensorValues v{};
  for (float& s : v.sonar) s = libagent::kSonarNoEcho;
  float* s = v.sensors;
  int found = 0;
  for (std::uint32_t k = 0; k < map.via.map.size; ++k) {
    const msgpack::object_kv& kv = map.via.map.ptr[k];
    if (kv.key.type != msgpack::type::STR) throw LolaError("LoLA sensor packet: a key is not a string");
    const std::string key(kv.key.via.str.ptr, kv.key.via.str.size);
    if (key == "RobotConfig") continue;  // the robot's ids: nothing for the robot code
    int index = -1;
    for (int i = 0; i < kNumSensorKeys; ++i)
      if (kSensorKeys[i].name == key) index = i;
    if (index < 0) throw LolaError("LoLA sensor packet: unknown key " + key);
    ++found;
    const std::vector<float> a = numbers(kv.val, key, static_cast<std::size_t>(kSensorKeys[index].length));
    switch (static_cast<SensorKey>(index)) {
      case SensorKey::Position:
        for (int j = 0; j < libagent::kNumJoints; ++j) v.joints.angles[j] = a[lolaJointOf(j)];
        break;
      case SensorKey::Stiffness:
        for (int j = 0; j < libagent::kNumJoints; ++j) v.joints.stiffnesses[j] = a[lolaJointOf(j)];
        break;
      case SensorKey::Temperature:
        for (int j = 0; j < libagent::kNumJoints; ++j) v.joints.temperatures[j] = a[lolaJointOf(j)];
        break;
      case SensorKey::Current:
        for (int j = 0; j < libagent::kNumJoints; ++j) v.joints.currents[j] = a[lolaJointOf(j)];
        break;
      case SensorKey::Gyroscope:  // LoLA's sign back to the body rate, then the V5's slot sign
        for (int i = 0; i < 3; ++i)
          s[S::InertialSensor_GyroscopeX + i] =
              static_cast<float>(libagent::inertial::kGyroscopeSign[i] * kGyroscopeSign[i] * a[i]);
        break;
      case SensorKey::Accelerometer:  // the same, for the specific force
        for (int i = 0; i < 3; ++i)
          s[S::InertialSensor_AccelerometerX + i] =
              static_cast<float>(libagent::inertial::kAccelerometerSign[i] * kAccelerometerSign[i] * a[i]);
        break;
      case SensorKey::Angles:
        s[S::InertialSensor_AngleX] = a[0];
        s[S::InertialSensor_AngleY] = a[1];
        break;
      case SensorKey::FSR:  // FSR, Touch, Battery, Sonar: to the V5's slots (Slots.hpp)
        for (int i = 0; i < kNumFsrs; ++i) s[kFsrSlots[i]] = a[i];
        break;
      case SensorKey::Touch:
        for (int i = 0; i < kNumTouch; ++i)
          if (kTouchSlots[i] != kNoSensorSlot) s[kTouchSlots[i]] = a[i];
        break;
      case SensorKey::Battery:
        for (int i = 0; i < kNumBattery; ++i)
          if (kBatterySlots[i] != kNoSensorSlot) s[kBatterySlots[i]] = a[i];
        break;
      case SensorKey::Sonar:
        for (int i = 0; i < 2; ++i) v.sonar[kSonarEchoes[i]] = a[i];
        break;
      case SensorKey::Status:
      case SensorKey::RobotConfig:
        break;  // the motors' temperature states: the temperatures are read instead
    }
  }
  if (found != kNumSensorKeys - 1) throw LolaError("LoLA sensor packet: " + std::to_string(found + 1) +
                                                   " of LoLA's " + std::to_string(kNumSensorKeys) + " keys");
  return v;
}

std::string actuatorMap(const libagent::JointValues& joints) {
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> pk(buffer);
  pk.pack_map(2);
  for (const char* key : {"Position", "Stiffness"}) {
    pk.pack(std::string(key));
    pk.pack_array(kNumJoints);
    char bytes[kFloat32Bytes];
    for (int l = 0; l < kNumJoints; ++l) {
      const int j = libagentJointOf(l);
      const float x = key[0] == 'P' ? joints.angles[j] : std::max(0.f, joints.stiffnesses[j]);
      writeFloat32(bytes, x);  // float32 always, as real clients send (Float32.hpp)
      buffer.write(bytes, kFloat32Bytes);
    }
  }
  return std::string(buffer.data(), buffer.size());
}

LolaConnection LolaConnection::connect(const std::string& path, double timeout_s) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof(address.sun_path))
    throw LolaError("LoLA socket \"" + path + "\": the path must have 1.." +
                    std::to_string(sizeof(address.sun_path) - 1) + " characters");
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw LolaError("LoLA socket " + path + ": socket: " + std::strerror(errno));
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0)
      return LolaConnection(fd, path);
    const int e = errno;
    ::close(fd);
    if (std::chrono::steady_clock::now() >= deadline)
      throw LolaError("LoLA socket " + path + ": cannot connect: " + std::strerror(e));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

LolaConnection::LolaConnection(LolaConnection&& o) noexcept
    : fd_(o.fd_), path_(std::move(o.path_)), packet_(o.packet_), packets_(o.packets_) {
  o.fd_ = -1;
}

LolaConnection::~LolaConnection() { close(); }

void LolaConnection::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool LolaConnection::readRest(std::size_t have) {
  while (have < packet_.size()) {
    const ssize_t n = ::recv(fd_, packet_.data() + have, packet_.size() - have, 0);
    if (n > 0) {
      have += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    close();  // the other end has gone (0: closed; an error: reset)
    return false;
  }
  ++packets_;
  return true;
}

bool LolaConnection::waitTick() {
  if (fd_ < 0) return false;
  return readRest(0);
}

bool LolaConnection::takeTick() {
  if (fd_ < 0) return false;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  return readRest(0);  // the packet was sent whole: the rest, if any, is on its way
}

libagent::SensorValues LolaConnection::readSensors() const {
  return sensorValuesFromPacket(packet_.data(), packet_.size());
}

bool LolaConnection::writeActuators(const libagent::JointValues& joints) {
  if (fd_ < 0) return false;
  const std::string map = actuatorMap(joints);
  std::size_t done = 0;
  while (done < map.size()) {
    const ssize_t n = ::send(fd_, map.data() + done, map.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    close();
    return false;
  }
  return true;
}

}  // namespace common::lola
