// The command lines of simswift and simswift-agent, declared with CLI11 (the
// parser and --help read the same declarations), and the checks their
// options share. Each check is a CLI11 transform: it reads the option's text
// by the project's rule and either says what is wrong (CLI11 puts the
// option's name in front: "--seed: must be ...") or rewrites the text in a
// form CLI11's own conversion reads exactly (CLI11 alone would read "010" as
// octal and a decimal through long double).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace simswift::cli {

// A number as strtod reads it, the whole text, finite; nothing otherwise.
std::optional<double> parseNumber(const std::string& text);

// A number in [lo, hi] ("bad value 'x' (must be in [lo, hi])"); with
// `whole`, a whole one (1e3 is 1000), for an integer option.
CLI::Validator number(double lo, double hi, bool whole = false);
// Any finite number ("not a number: 'x'").
CLI::Validator number();
// A whole number in [lo, hi] by the seed reader's rule (common/config/Seed.hpp:
// digits only, every 64-bit value exact).
CLI::Validator wholeNumber(uint64_t lo, uint64_t hi);
// A seed: any 64-bit value, the seed reader's rule and its message.
CLI::Validator seed();
// One of `words` ("must be a, b or c (got 'x')").
CLI::Validator oneOf(std::vector<std::string> words);
// Not the empty string ("needs a value").
CLI::Validator nonEmpty();

// --shard K/N: run only the items K-1, K-1+N, ... (1 <= K <= N <= max),
// K and N by the seed reader's rule.
struct Shard {
  int k = 1;
  int n = 1;
};
std::optional<Shard> parseShard(const std::string& text, int max);
CLI::Validator shard(int max);

// "simswift experiment merge": the program and the subcommands down to `cmd`.
std::string commandName(const CLI::App& cmd);

// Parses argv into `app`'s declarations. Returns nothing when the command
// is to run; else the exit code after printing: 0 for --help (stdout, the
// help of the subcommand it follows) and --version, 2 for a bad command line
// (stderr: the subcommand, the message naming the option, where the help is).
std::optional<int> parse(CLI::App& app, int argc, const char* const* argv);

// A bad command line found after parsing (options that go together, a name
// a file must hold): prints as parse() does and returns 2.
int usageError(const CLI::App& cmd, const std::string& message);

}  // namespace simswift::cli
