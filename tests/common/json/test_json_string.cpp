// common/json: the one JSON string writer the recording and the viewer share.
#include <gtest/gtest.h>

#include <string>

#include "common/json/JsonString.hpp"

namespace {

TEST(JsonString, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(common::json::quote("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
  EXPECT_EQ(common::json::quote(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(common::json::quote("m\xc3\xa9tre"), "\"m\xc3\xa9tre\"");  // UTF-8 copied
  std::string out = "x:";
  common::json::appendQuoted(out, "");
  EXPECT_EQ(out, "x:\"\"");
}

}  // namespace
