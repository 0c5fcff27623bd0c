// The error every configuration loader (the simulator's field and scenario, the
// robot program's config) throws for bad
// input. Its message always names the file, the line and the key path, e.g.
//   fields/x.yaml:12: field.ball.mass: must be > 0 (got -1)
// and it keeps those parts apart (the public API's ConfigError hands them
// on as they were set, nothing reads them back out of the text).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace common::config {

struct ConfigError : std::runtime_error {
  // A message that names no file (a setting given in code, e.g. World's).
  explicit ConfigError(const std::string& message) : std::runtime_error(message) {}
  // "file:line: key: what", or "file:line: what" with no key.
  ConfigError(std::string file_, int line_, std::string key_, const std::string& what)
      : std::runtime_error(file_ + ":" + std::to_string(line_) + ": " + (key_.empty() ? "" : key_ + ": ") + what),
        file(std::move(file_)),
        line(line_),
        key(std::move(key_)) {}

  std::string file;  // "" if the message names none
  int line = 0;      // 1-based; 0 if none
  std::string key;   // dotted key path; "" if none
};

// Where in a file a value was given: the parts a ConfigError about it
// carries, kept apart for an error raised after the file was read (an
// experiment robot's behaviour, checked with its overrides; YamlReader::place).
struct ConfigPlace {
  std::string file;
  int line = 0;     // 1-based
  std::string key;  // dotted key path
};

}  // namespace common::config
