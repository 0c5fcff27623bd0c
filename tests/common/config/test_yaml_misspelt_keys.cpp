// Misspelt keys (common/config/YamlReader.hpp, issue 34 item 5): a key that
// looks like a misspelling of a required key nobody found is named at its
// own line ("did you mean"), not reported as a missing key at its map's
// first line; an unknown key near a known one gets the same hint; short
// keys and keys the reader has already taken are never taken for typos.
#include <gtest/gtest.h>

#include <string>

#include "common/config/YamlReader.hpp"
#include "tests/support/ConfigErrors.hpp"

using common::config::Range;
using common::config::YamlReader;

namespace {

// Reads `text` as a map with a required `required` number, then the
// optional ones, then finish(); the error's message, or "".
std::string misspeltKeyError(const std::string& text, const std::string& required) {
  return simswift::testing::configError([&] {
    const YAML::Node root = YamlReader::parse(text, "r.yaml");
    YamlReader r(root, "r.yaml");
    r.number("count", 1.0);  // optional, read first
    r.number(required, Range::any());
    r.number("spacing", 1.0);
    r.finish();
  });
}

}  // namespace

TEST(YamlMisspeltKeys, ARequiredKeysNearMissIsNamedAtItsLine) {
  // Before issue 34: "r.yaml:1: trials_per_position: missing required key".
  EXPECT_EQ(misspeltKeyError("count: 2\n\ntrials_per_positon: 1\n", "trials_per_position"),
            "r.yaml:3: unknown key 'trials_per_positon' in <document> (did you mean trials_per_position? a required "
            "key, missing)");
  // Letter case, a swap, one letter gone or added, two edits in a long key.
  for (const char* typo : {"Trials_Per_Position", "trials_per_psoition", "trials_per_postion",
                           "trials_per_positionn", "trails_per_postion"})
    EXPECT_EQ(misspeltKeyError(std::string("count: 2\n") + typo + ": 1\n", "trials_per_position").rfind(
                  "r.yaml:2: unknown key '" + std::string(typo) + "' in <document> (did you mean trials_per_position?",
                  0),
              0u)
        << typo;
  // A key the reader has already taken is no typo: count is count.
  EXPECT_EQ(misspeltKeyError("count: 2\n", "counts"), "r.yaml:1: counts: missing required key");
  // Short keys: x and y are both keys, so no guess; nor a different first
  // letter in keys of up to 7 letters (name / game).
  EXPECT_EQ(misspeltKeyError("count: 2\ny: 1\n", "x"), "r.yaml:1: x: missing required key");
  EXPECT_EQ(misspeltKeyError("count: 2\ngame: 1\n", "name"), "r.yaml:1: name: missing required key");
  // Far from it: missing, as before.
  EXPECT_EQ(misspeltKeyError("count: 2\ntrials: 1\n", "trials_per_position"),
            "r.yaml:1: trials_per_position: missing required key");
}

TEST(YamlMisspeltKeys, AnUnknownKeyNearAKnownOneGetsTheHint) {
  EXPECT_EQ(misspeltKeyError("count: 2\nlimit: 1\nspaceing: 3\n", "limit"),
            "r.yaml:3: unknown key 'spaceing' in <document> (did you mean spacing?); expected one of count, limit, "
            "spacing");
  EXPECT_EQ(misspeltKeyError("count: 2\nlimit: 1\nwhatever: 3\n", "limit"),
            "r.yaml:3: unknown key 'whatever' in <document>; expected one of count, limit, spacing");
}
