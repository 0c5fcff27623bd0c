#include "app/cli/CommandLine.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/config/Seed.hpp"

namespace simswift::cli {

namespace {

// %g: the bounds as a user would write them (0.01, 1e+06).
std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The double exactly, in hex (CLI11 reads it back through strtold: no
// rounding on the way).
std::string exactText(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

// A whole double in decimal digits (for options read into an integer type).
std::string wholeText(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

}  // namespace

std::optional<double> parseNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

CLI::Validator number(double lo, double hi, bool whole) {
  const std::string range = std::string(whole ? "a whole number in [" : "in [") + shortNumber(lo) + ", " +
                            shortNumber(hi) + "]";
  return CLI::Validator(
      [lo, hi, whole, range](std::string& text) -> std::string {
        // A whole number is written in decimal digits (a leading '-' allowed),
        // as a seed is (common/config/Seed.hpp): no hex, exponent or spaces.
        const bool digits = !text.empty() && text.find_first_not_of("0123456789", text[0] == '-' ? 1 : 0) ==
                                                 std::string::npos && text != "-";
        const std::optional<double> v = parseNumber(text);
        if (!v || !(*v >= lo && *v <= hi) || (whole && (*v != std::floor(*v) || !digits)))
          return "bad value '" + text + "' (must be " + range + ")";
        text = whole ? wholeText(*v) : exactText(*v);
        return "";
      },
      "", "");
}

CLI::Validator number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> v = parseNumber(text);
        if (!v) return "not a number: '" + text + "'";
        text = exactText(*v);
        return "";
      },
      "", "");
}

CLI::Validator wholeNumber(uint64_t lo, uint64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const std::optional<uint64_t> v = common::config::parseSeed(text);
        if (!v || *v < lo || *v > hi)
          return "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got '" +
                 text + "')";
        text = std::to_string(*v);  // decimal: CLI11 reads a leading 0 as octal
        return "";
      },
      "", "");
}

CLI::Validator seed() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<uint64_t> v = common::config::parseSeed(text);
        if (!v) return std::string("must be ") + common::config::kSeedRange + " (got '" + text + "')";
        text = std::to_string(*v);
        return "";
      },
      "", "");
}

CLI::Validator oneOf(std::vector<std::string> words) {
  std::string list;
  for (size_t i = 0; i < words.size(); ++i)
    list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return CLI::Validator(
      [words, list](std::string& text) -> std::string {
        for (const std::string& w : words)
          if (text == w) return "";
        return "must be " + list + " (got '" + text + "')";
      },
      "", "");
}

CLI::Validator nonEmpty() {
  return CLI::Validator([](std::string& text) -> std::string { return text.empty() ? "needs a value" : ""; }, "",
                        "");
}

std::optional<Shard> parseShard(const std::string& text, int max) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const std::optional<uint64_t> k = common::config::parseSeed(text.substr(0, slash));
  const std::optional<uint64_t> n = common::config::parseSeed(text.substr(slash + 1));
  if (!k || !n || *k < 1 || *k > *n || *n > static_cast<uint64_t>(max)) return std::nullopt;
  return Shard{static_cast<int>(*k), static_cast<int>(*n)};
}

CLI::Validator shard(int max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        if (parseShard(text, max)) return "";
        return "needs K/N with 1 <= K <= N <= " + std::to_string(max) + " (got '" + text + "')";
      },
      "", "");
}

std::string commandName(const CLI::App& cmd) {
  const CLI::App* parent = cmd.get_parent();
  return parent ? commandName(*parent) + " " + cmd.get_name() : cmd.get_name();
}

std::optional<int> parse(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);  // the help of the last subcommand given
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return 0;
  } catch (const CLI::ParseError& e) {
    // The subcommand the error is in: the last one given.
    const CLI::App* cmd = &app;
    for (std::vector<CLI::App*> given = app.get_subcommands(); !given.empty(); given = given[0]->get_subcommands())
      cmd = given[0];
    return usageError(*cmd, e.what());
  }
}

int usageError(const CLI::App& cmd, const std::string& message) {
  const std::string name = commandName(cmd);
  std::fprintf(stderr, "%s: %s\n(%s --help lists the options)\n", name.c_str(), message.c_str(), name.c_str());
  return 2;
}

}  // namespace simswift::cli
