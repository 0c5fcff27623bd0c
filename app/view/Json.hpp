// The little JSON the viewer's server needs (docs/viewer.md): a validator
// for the recording's message payloads (they are passed to the page as they
// are, so each is checked once when the file is opened). Its answers quote
// strings with common/json. No parser: the page reads the JSON.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace simswift::view::json {

// npos if `text` is one JSON value (RFC 8259; surrounding white space
// allowed, nesting at most 128 deep), else the offset of the first error.
std::size_t invalidAt(std::string_view text);

}  // namespace simswift::view::json
