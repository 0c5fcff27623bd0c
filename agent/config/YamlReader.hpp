// A small typed reader over yaml-cpp for configuration files (fields,
// scenarios). It keeps the key path and the file name so every error says
// where it is:
//
//   fields/x.yaml:12: field.ball.mass: must be > 0 (got -1)
//
// Usage: parse the text, then walk maps with a YamlReader. Each getter
// records the key it was asked for; `finish()` then rejects any key in the
// map that nobody asked for (typos such as 'bal' for 'ball').
//
//   YAML::Node root = YamlReader::parse(text, "fields/x.yaml");
//   YamlReader top(root, "fields/x.yaml");
//   YamlReader f = top.map("field");              // required map
//   double len = f.number("length", 9.0, Range::positive());
//   for (YamlReader item : f.list("lines")) { ... item.finish(); }
//   f.finish();
//   top.finish();
//
// All getters throw ConfigError. Absent optional keys return the default.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "agent/config/ConfigError.hpp"

namespace agent::config {

// Allowed interval for a number; the bounds are checked and quoted in errors.
struct Range {
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;  // open = strict inequality

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::nullopt, true, false}; }     // > 0
  static Range nonNegative() { return {0.0, std::nullopt, false, false}; } // >= 0
  static Range atLeast(double v) { return {v, std::nullopt, false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; } // a <= x <= b
  static Range openClosed(double a, double b) { return {a, b, true, false}; } // a < x <= b

  bool contains(double v) const;
  std::string describe() const;  // e.g. "must be > 0"
};

// Configuration files are small; anything bigger is refused before parsing.
constexpr size_t kMaxConfigBytes = 1u << 20;

class YamlReader {
 public:
  // Parses YAML text; a syntax error becomes a ConfigError with the line.
  static YAML::Node parse(const std::string& text, const std::string& file);
  // Reads and parses a file; a missing file, a directory or a file over
  // kMaxConfigBytes is a ConfigError.
  static YAML::Node parseFile(const std::string& path);

  // `node` must be a map (checked lazily by the getters); `path` is the
  // dotted key path of `node` ("" for the document root).
  YamlReader(YAML::Node node, std::string file, std::string path = "");

  bool has(const std::string& key) const;  // also marks the key as known

  // Numbers. With a default: optional. Without: required.
  double number(const std::string& key, double def, const Range& r = Range::any()) const;
  double number(const std::string& key, const Range& r = Range::any()) const;
  int integer(const std::string& key, int def, const Range& r = Range::any()) const;
  int integer(const std::string& key, const Range& r = Range::any()) const;
  bool boolean(const std::string& key, bool def) const;
  bool boolean(const std::string& key) const;
  std::string string(const std::string& key, const std::string& def) const;
  std::string string(const std::string& key) const;
  // One of `choices`.
  std::string choice(const std::string& key, const std::string& def,
                     const std::vector<std::string>& choices) const;
  // A fixed-length list of numbers, e.g. [x, y]. Required.
  std::vector<double> numbers(const std::string& key, size_t count,
                              const Range& r = Range::any()) const;
  std::vector<double> numbers(const std::string& key, const std::vector<double>& def,
                              const Range& r = Range::any()) const;

  // A nested map: required, or optional (nullopt when absent).
  YamlReader map(const std::string& key) const;
  std::optional<YamlReader> optionalMap(const std::string& key) const;
  // A list of maps (an absent key gives an empty list). Each element's path
  // is "key[i]".
  std::vector<YamlReader> list(const std::string& key) const;

  // Rejects keys this reader was never asked about. Call after reading.
  void finish() const;

  // Throws ConfigError "file:line: path.key: message" (line of the key's
  // value, or of this map if the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // Same, about this map itself.
  [[noreturn]] void fail(const std::string& message) const;

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const;

 private:
  YAML::Node get(const std::string& key) const;      // undefined node if absent
  YAML::Node require(const std::string& key) const;  // fails if absent
  double toNumber(const YAML::Node& n, const std::string& key) const;
  void checkMap() const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  mutable std::vector<std::string> known_;  // keys asked for, in order
};

}  // namespace agent::config
