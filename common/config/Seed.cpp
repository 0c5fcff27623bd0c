#include "common/config/Seed.hpp"

namespace common::config {

std::optional<uint64_t> parseSeed(const std::string& text) {
  if (text.empty() || text.size() > 20) return std::nullopt;
  uint64_t v = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    const uint64_t d = static_cast<uint64_t>(c - '0');
    if (v > (UINT64_MAX - d) / 10) return std::nullopt;  // v * 10 + d would wrap
    v = v * 10 + d;
  }
  return v;
}

uint64_t readSeed(const YamlReader& r, const std::string& key, uint64_t def) {
  if (!r.has(key)) return def;
  const YAML::Node n = r.node()[key];
  const std::string text = n.IsScalar() ? n.Scalar() : "";
  const std::optional<uint64_t> seed = parseSeed(text);
  if (!seed) r.fail(key, std::string("must be ") + kSeedRange + (n.IsScalar() ? " (got '" + text + "')" : ""));
  return *seed;
}

uint64_t readSeed(const YamlReader& r, const std::string& key) {
  if (!r.has(key)) r.missing(key, "missing required key");
  return readSeed(r, key, 0);
}

}  // namespace common::config
