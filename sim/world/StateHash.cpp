// World::stateHash: FNV-1a (64 bit) over the raw bit patterns of every
// body's position, quaternion, linear and angular velocity, in a fixed
// order (ball, then robots by index, links by model index). Two runs that
// agree bit for bit give the same hash; any difference in any bit changes it.
#include <cstring>

#include "sim/world/WorldImpl.hpp"

namespace simswift {

namespace {

constexpr uint64_t kFnvOffset = 1469598103934665603ULL;
constexpr uint64_t kFnvPrime = 1099511628211ULL;

void mix(uint64_t& h, const dReal* v, int n) {
  for (int i = 0; i < n; ++i) {
    unsigned char bytes[sizeof(dReal)];
    std::memcpy(bytes, &v[i], sizeof(dReal));
    for (unsigned char b : bytes) {
      h ^= b;
      h *= kFnvPrime;
    }
  }
}

void mixBody(uint64_t& h, dBodyID b) {
  mix(h, dBodyGetPosition(b), 3);
  mix(h, dBodyGetQuaternion(b), 4);
  mix(h, dBodyGetLinearVel(b), 3);
  mix(h, dBodyGetAngularVel(b), 3);
}

}  // namespace

uint64_t World::stateHash() const {
  uint64_t h = kFnvOffset;
  mixBody(h, impl_->ball);
  for (const auto& r : robots_) {
    const size_t n = r->model().links().size();
    for (size_t l = 0; l < n; ++l) {
      if (dBodyID b = r->body(static_cast<int>(l))) mixBody(h, b);
    }
  }
  return h;
}

}  // namespace simswift
