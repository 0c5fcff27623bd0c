// A JSON string (RFC 8259), quotes included: one home for the recording's
// writer (sim/record/Json) and the viewer's answers (app/view). `"` and `\`
// escaped, control characters as \u00XX, every other byte copied (UTF-8
// passes through).
#pragma once

#include <string>
#include <string_view>

namespace common::json {

// Appends `s` quoted to `out`.
void appendQuoted(std::string& out, std::string_view s);

inline std::string quote(std::string_view s) {
  std::string out;
  appendQuoted(out, s);
  return out;
}

}  // namespace common::json
