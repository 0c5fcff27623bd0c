// The parse-and-expect-error pattern of the loader tests, once: the message
// of the ConfigError a call throws, or "" when it throws none (so a test's
// find() on it then fails and prints the call's input).
#pragma once

#include <string>

#include "common/config/ConfigError.hpp"

namespace simswift::testing {

template <class Parse>
std::string configError(Parse&& parse) {
  try {
    parse();
  } catch (const common::config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace simswift::testing
