// A small typed reader over yaml-cpp for configuration files (fields,
// scenarios). It keeps the key path and the file name so every error says
// where it is:
//
//   fields/x.yaml:12: field.ball.mass: must be > 0 (got -1)
//
// Usage: parse the text, then walk maps with a YamlReader. Each getter
// records the key it was asked for; `finish()` then rejects any key in the
// map that nobody asked for (typos such as 'bal' for 'ball': "did you mean
// ball?"). A required key that is absent while a near miss of it is there
// is reported as that misspelling at its own line (missing()), not as a
// missing key at the map's first line.
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
//
// Limits, each refused by parse() with the file and a line, so that any
// input is accepted or refused in time linear in its size:
//   - kMaxConfigBytes (256 KB): configuration files are a few KB;
//   - a NUL byte anywhere (not a text file; YAML does not allow it);
//   - nesting deeper than yaml-cpp's own guard (500 levels of its recursion
//     in Debian's 0.7: about 500 block or flow levels), said as such;
//   - kMaxConfigNodes nodes counting each use of an alias in full (the
//     readers walk an alias as often as it is used: a few KB of nested
//     aliases would otherwise expand to billions of nodes).
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/config/ConfigError.hpp"

namespace common::config {

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

// Configuration files are small (the largest shipped is 3.5 KB); anything
// bigger is refused before parsing. yaml-cpp reads dense YAML at about
// 1.6 MB/s here and the readers take as long again: a 1 MB experiment of
// 180,000 nodes took 0.63 s to parse and 1.0-1.4 s to check.
constexpr size_t kMaxConfigBytes = 256u << 10;
// Nodes of one document, aliases counted at every use: twice what the
// densest 256 KB of plain YAML ("[1,1,1,...]") holds.
constexpr size_t kMaxConfigNodes = 1u << 18;

// Throws ConfigError "file:1: N bytes is more than a configuration file can
// be (256 KB)" when `bytes` is over kMaxConfigBytes.
void checkConfigSize(unsigned long long bytes, const std::string& file);

// Nodes of `root` counting an aliased map or list once per use (as readers
// walk it), in time linear in the distinct nodes; stops counting once past
// `limit` (the result is then some value above it).
size_t expandedNodes(const YAML::Node& root, size_t limit);

class YamlReader {
 public:
  // Parses YAML text; a syntax error becomes a ConfigError with the line.
  static YAML::Node parse(const std::string& text, const std::string& file);
  // The text of a configuration file, the one way every loader reads one: a
  // directory ("path:1: is a directory, not a <kind>"), a file over
  // kMaxConfigBytes (refused before it is read) or one that cannot be opened
  // ("path:1: cannot open <kind>") is a ConfigError.
  static std::string readFile(const std::string& path, const std::string& kind = "file");
  // Reads (readFile) and parses a file.
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
  // One of an enum's values by its name in `names` (def: one of them).
  template <class E>
  E enumChoice(const std::string& key, E def, const std::vector<std::pair<std::string, E>>& names) const {
    std::string def_name;
    std::vector<std::string> choices;
    for (const auto& [name, value] : names) {
      choices.push_back(name);
      if (value == def) def_name = name;
    }
    const std::string got = choice(key, def_name, choices);
    for (const auto& [name, value] : names)
      if (name == got) return value;
    return def;
  }
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

  // This map's keys in the file's order, each with its 1-based line, for
  // readers whose keys are data (a launched program's env:, a test's
  // operator): the one way to walk a map's keys. Marks none as known.
  struct Key {
    std::string name;
    int line = 1;
  };
  std::vector<Key> keys() const;

  // Throws ConfigError "file:line: path.key: message" (line of the key's
  // value, or of this map if the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // Same, about this map itself.
  [[noreturn]] void fail(const std::string& message) const;
  // `key` is absent but needed: a key of this map that nobody asked for and
  // that looks like a misspelling of it (case, one or two letters) is named
  // at its own line, "unknown key 'trials_per_positon' in <document> (did
  // you mean trials_per_position? a required key, missing)"; else fail(key,
  // message). Required getters call it; so do readers whose key is required
  // only sometimes.
  [[noreturn]] void missing(const std::string& key, const std::string& message) const;
  // The check alone: throws as missing() does if this map holds a
  // misspelling of `key`, else returns (a key that may be given here or in
  // an enclosing map).
  void checkMisspelling(const std::string& key) const;

  // Where `key` is given (the line of its value, or of this map if the key
  // is absent, as fail names it), or this map itself: for errors raised
  // after reading (ConfigPlace). Marks no key as known.
  ConfigPlace place(const std::string& key) const;
  ConfigPlace place() const;

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const;

 private:
  YAML::Node get(const std::string& key) const;      // undefined node if absent
  YAML::Node require(const std::string& key) const;  // fails if absent
  double toNumber(const YAML::Node& n, const std::string& key) const;
  // Fails unless the node is a map (or empty) whose keys are all plain
  // scalars: a list, a map or nothing as a key ("? [never]: ..." in YAML's
  // complex-key syntax) is refused at the key's line, once per reader.
  void checkMap() const;

  mutable bool keys_checked_ = false;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  mutable std::vector<std::string> known_;  // keys asked for, in order
};

}  // namespace common::config
