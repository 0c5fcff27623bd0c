// The errors simswift's API throws for bad input files (Simulation.hpp,
// Experiment.hpp); misuse is std::logic_error, a run that fails
// std::runtime_error.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace simswift::api {

// A configuration error (a scenario, experiment, model or field file), split
// into where and what:
//   file "walk.yaml", line 7, key "robots[1].team", what() the whole message.
struct ConfigError : std::runtime_error {
  ConfigError(const std::string& message, std::string file_, int line_, std::string key_)
      : std::runtime_error(message), file(std::move(file_)), line(line_), key(std::move(key_)) {}
  std::string file;
  int line = 0;      // 0 if the message names none
  std::string key;   // dotted key path ("" if none)
};

}  // namespace simswift::api
