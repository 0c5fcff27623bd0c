// Typed YAML reading with file:line:key errors. See YamlReader.hpp.
#include "common/config/YamlReader.hpp"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace common::config {

namespace {

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// How a scalar looked in the file, for "got ..." in messages.
std::string shown(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "?";
}

// A key as shown in a message: long ones cut (a 1 MB key is a typo, not
// something to print in full).
std::string clip(const std::string& s) {
  return s.size() <= 80 ? s : s.substr(0, 80) + "...(" + std::to_string(s.size()) + " bytes)";
}

// expandedNodes: a collection's total is kept by its position in the file
// (an alias is the very node it names, so it has the same mark).
size_t countNodes(const YAML::Node& n, size_t limit, std::unordered_map<size_t, size_t>& seen) {
  if (!n.IsMap() && !n.IsSequence()) return 1;
  const YAML::Mark m = n.Mark();
  const bool keyed = !m.is_null();
  if (keyed)
    if (auto it = seen.find(static_cast<size_t>(m.pos)); it != seen.end()) return it->second;
  size_t total = 1;
  for (auto it = n.begin(); it != n.end() && total <= limit; ++it) {
    if (n.IsMap()) {
      total += countNodes(it->first, limit, seen);
      total += countNodes(it->second, limit, seen);
    } else {
      total += countNodes(*it, limit, seen);
    }
  }
  if (keyed) seen[static_cast<size_t>(m.pos)] = total;
  return total;
}

// Optimal-string-alignment distance (insertions, deletions, substitutions
// and swaps of two neighbours, each 1) between two keys, stopping early
// once every path is past `limit` (the result is then limit + 1).
size_t editDistance(const std::string& a, const std::string& b, size_t limit) {
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > limit) return limit + 1;
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t row_min = d[i][0];
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);  // two neighbours swapped
      row_min = std::min(row_min, d[i][j]);
    }
    if (row_min > limit) return limit + 1;
  }
  return d[a.size()][b.size()];
}

// Whether `written` looks like a misspelling of the valid key `valid`: the
// same but for letter case, or a few edits away: none for keys of up to 3
// letters (one edit makes another key: x / y), 1 up to 7 letters with the
// first letter right (name / game are two keys), 2 beyond.
bool nearMiss(const std::string& written, const std::string& valid) {
  if (written == valid || written.size() > 200) return false;
  std::string lw = written, lv = valid;
  for (char& c : lw) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (char& c : lv) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lw == lv) return true;
  if (valid.size() <= 3 || (valid.size() <= 7 && lw[0] != lv[0])) return false;
  const size_t limit = valid.size() <= 7 ? 1 : 2;
  return editDistance(lw, lv, limit) <= limit;
}

}  // namespace

size_t expandedNodes(const YAML::Node& root, size_t limit) {
  std::unordered_map<size_t, size_t> seen;
  return countNodes(root, limit, seen);
}

bool Range::contains(double v) const {
  if (lo && (lo_open ? !(v > *lo) : !(v >= *lo))) return false;
  if (hi && (hi_open ? !(v < *hi) : !(v <= *hi))) return false;
  return true;
}

std::string Range::describe() const {
  if (lo && hi) {
    return "must be in " + std::string(lo_open ? "(" : "[") + fmt(*lo) + ", " + fmt(*hi) +
           (hi_open ? ")" : "]");
  }
  if (lo) return std::string("must be ") + (lo_open ? "> " : ">= ") + fmt(*lo);
  if (hi) return std::string("must be ") + (hi_open ? "< " : "<= ") + fmt(*hi);
  return "must be a number";
}

void checkConfigSize(unsigned long long bytes, const std::string& file) {
  if (bytes > kMaxConfigBytes)
    throw ConfigError(file, 1, "",
                      std::to_string(bytes) + " bytes is more than a configuration file can be (" +
                          std::to_string(kMaxConfigBytes >> 10) + " KB)");
}

YAML::Node YamlReader::parse(const std::string& text, const std::string& file) {
  checkConfigSize(text.size(), file);
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    const long line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    throw ConfigError(file, static_cast<int>(line), "", "contains a NUL byte (not a text file?)");
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp says "bad file" here; its mark is where it stopped.
    throw ConfigError(file, e.mark.line + 1, "",
                      "YAML nested too deep: yaml-cpp stops at " + std::to_string(e.depth()) +
                          " levels of recursion (a configuration file needs fewer than 10)");
  } catch (const YAML::Exception& e) {
    // e.mark.line is 0-based; e.msg is yaml-cpp's text without the position.
    throw ConfigError(file, e.mark.line + 1, "", "YAML syntax error: " + e.msg);
  }
  // Only an alias ('*') can make the readers' walk longer than the text.
  if (text.find('*') != std::string::npos) {
    const size_t nodes = expandedNodes(root, kMaxConfigNodes);
    if (nodes > kMaxConfigNodes)
      throw ConfigError(file, 1, "",
                        "more than " + std::to_string(kMaxConfigNodes) +
                            " YAML nodes, counting each use of an alias in full (aliases of aliases?)");
  }
  return root;
}

std::string YamlReader::readFile(const std::string& path, const std::string& kind) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    const bool vowel = !kind.empty() && std::string("aeiou").find(kind[0]) != std::string::npos;
    throw ConfigError(path, 1, "", "is a directory, not " + std::string(vowel ? "an " : "a ") + kind);
  }
  // yaml-cpp reads everything at once: a huge file is refused before it is read.
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) checkConfigSize(size, path);
  std::ifstream in(path);
  if (!in) throw ConfigError(path, 1, "", "cannot open " + kind);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

YAML::Node YamlReader::parseFile(const std::string& path) { return parse(readFile(path), path); }

YamlReader::YamlReader(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

std::string YamlReader::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

// The 1-based line of `n`, else of `fallback`; an empty document has no
// marks: its line is 1.
static int lineOf(const YAML::Node& n, const YAML::Node& fallback) {
  const YAML::Mark m = (n.IsDefined() && !n.Mark().is_null()) ? n.Mark() : fallback.Mark();
  return m.is_null() ? 1 : m.line + 1;
}

ConfigPlace YamlReader::place(const std::string& key) const {
  const YAML::Node& cn = node_;
  const YAML::Node n = cn.IsMap() ? cn[key] : YAML::Node(YAML::NodeType::Undefined);  // const: never inserts
  return {file_, lineOf(n, node_), keyPath(key)};
}

ConfigPlace YamlReader::place() const { return {file_, lineOf(node_, node_), path_}; }

void YamlReader::fail(const std::string& key, const std::string& message) const {
  const int line = lineOf(get(key), node_);
  const std::string k = keyPath(key);
  // A key spelt "" keeps its empty slot in the text ("file:3: : ...").
  if (k.empty()) throw ConfigError(file_, line, "", ": " + message);
  throw ConfigError(file_, line, k, message);
}

void YamlReader::fail(const std::string& message) const {
  const int line = lineOf(node_, node_);
  // The document itself has no key: "<document>" is said in the text only.
  if (path_.empty()) throw ConfigError(file_, line, "", "<document>: " + message);
  throw ConfigError(file_, line, path_, message);
}

void YamlReader::missing(const std::string& key, const std::string& message) const {
  checkMisspelling(key);
  fail(key, message);
}

void YamlReader::checkMisspelling(const std::string& key) const {
  // A misspelling of it (a key nobody asked for yet) is named at its own
  // line: "missing" at the map's first line would hide the typo.
  if (node_.IsMap())
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      if (!it->first.IsScalar()) continue;
      const std::string& k = it->first.Scalar();
      if (std::find(known_.begin(), known_.end(), k) != known_.end() || !nearMiss(k, key)) continue;
      const YAML::Mark m = it->first.Mark();
      throw ConfigError(file_, m.is_null() ? 1 : m.line + 1, "",
                        "unknown key '" + clip(k) + "' in " + (path_.empty() ? std::string("<document>") : path_) +
                            " (did you mean " + key + "? a required key, missing)");
    }
}

void YamlReader::checkMap() const {
  // An empty value ("field:" with nothing under it) counts as an empty map.
  if (!node_.IsDefined() || node_.IsNull()) return;
  if (!node_.IsMap()) fail("expected a map of keys (got " + shown(node_) + ")");
  if (keys_checked_) return;
  // Every reader names keys by their text: a key that is a list, a map or
  // nothing (YAML's "? [never]: ..." or "~: ...") has none, and yaml-cpp
  // would throw its own unplaced "bad conversion" where a reader asked.
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YAML::Node k = it->first;  // a copy (a handle): `it->first` is a member of a temporary
    if (k.IsScalar()) continue;
    std::string got = "~";
    if (k.IsSequence() || k.IsMap()) {
      YAML::Emitter e;
      e << YAML::Flow << k;
      got = clip(e.c_str());
    }
    const YAML::Mark m = k.Mark().is_null() ? node_.Mark() : k.Mark();
    throw ConfigError(file_, m.is_null() ? 1 : m.line + 1, path_,
                      std::string(path_.empty() ? "<document>: " : "") + "a key must be a name, not " +
                          (k.IsSequence() ? "a list" : k.IsMap() ? "a map" : "null") + " (got " + got + ")");
  }
  keys_checked_ = true;
}

std::vector<YamlReader::Key> YamlReader::keys() const {
  checkMap();
  std::vector<Key> out;
  if (!node_.IsMap()) return out;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YAML::Mark m = it->first.Mark();
    out.push_back({it->first.Scalar(), m.is_null() ? 1 : m.line + 1});
  }
  return out;
}

YAML::Node YamlReader::get(const std::string& key) const {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  if (!node_.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node& cn = node_;
  return cn[key];  // const access: never inserts
}

bool YamlReader::has(const std::string& key) const {
  checkMap();
  return get(key).IsDefined();
}

YAML::Node YamlReader::require(const std::string& key) const {
  checkMap();
  YAML::Node n = get(key);
  if (!n.IsDefined()) missing(key, "missing required key");
  return n;
}

double YamlReader::toNumber(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(key, "expected a number (got " + shown(n) + ")");
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "expected a number (got " + shown(n) + ")");
  }
  if (!std::isfinite(v)) fail(key, "must be finite (got " + shown(n) + ")");
  return v;
}

double YamlReader::number(const std::string& key, double def, const Range& r) const {
  checkMap();
  if (!get(key).IsDefined()) return def;
  return number(key, r);
}

double YamlReader::number(const std::string& key, const Range& r) const {
  double v = toNumber(require(key), key);
  if (!r.contains(v)) fail(key, r.describe() + " (got " + fmt(v) + ")");
  return v;
}

int YamlReader::integer(const std::string& key, int def, const Range& r) const {
  checkMap();
  if (!get(key).IsDefined()) return def;
  return integer(key, r);
}

int YamlReader::integer(const std::string& key, const Range& r) const {
  double v = toNumber(require(key), key);
  if (v != std::floor(v) || std::fabs(v) > 2e9) {
    fail(key, "expected an integer (got " + fmt(v) + ")");
  }
  if (!r.contains(v)) fail(key, r.describe() + " (got " + fmt(v) + ")");
  return static_cast<int>(v);
}

bool YamlReader::boolean(const std::string& key, bool def) const {
  checkMap();
  if (!get(key).IsDefined()) return def;
  return boolean(key);
}

bool YamlReader::boolean(const std::string& key) const {
  YAML::Node n = require(key);
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "True" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "False" || s == "no" || s == "off") return false;
  }
  fail(key, "expected true or false (got " + shown(n) + ")");
}

std::string YamlReader::string(const std::string& key, const std::string& def) const {
  checkMap();
  if (!get(key).IsDefined()) return def;
  return string(key);
}

std::string YamlReader::string(const std::string& key) const {
  YAML::Node n = require(key);
  if (!n.IsScalar()) fail(key, "expected a string (got " + shown(n) + ")");
  return n.Scalar();
}

std::string YamlReader::choice(const std::string& key, const std::string& def,
                               const std::vector<std::string>& choices) const {
  std::string v = string(key, def);
  if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  fail(key, "expected one of " + list + " (got '" + v + "')");
}

std::vector<double> YamlReader::numbers(const std::string& key, size_t count,
                                        const Range& r) const {
  YAML::Node n = require(key);
  if (!n.IsSequence() || n.size() != count) {
    fail(key, "expected a list of " + std::to_string(count) + " numbers (got " + shown(n) + ")");
  }
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i) {
    double v = toNumber(n[i], key);
    if (!r.contains(v)) {
      fail(key, "element " + std::to_string(i) + " " + r.describe() + " (got " + fmt(v) + ")");
    }
    out.push_back(v);
  }
  return out;
}

std::vector<double> YamlReader::numbers(const std::string& key, const std::vector<double>& def,
                                        const Range& r) const {
  checkMap();
  if (!get(key).IsDefined()) return def;
  return numbers(key, def.size(), r);
}

YamlReader YamlReader::map(const std::string& key) const {
  YAML::Node n = require(key);
  YamlReader sub(n, file_, keyPath(key));
  sub.checkMap();
  return sub;
}

std::optional<YamlReader> YamlReader::optionalMap(const std::string& key) const {
  checkMap();
  if (!get(key).IsDefined()) return std::nullopt;
  return map(key);
}

std::vector<YamlReader> YamlReader::list(const std::string& key) const {
  checkMap();
  YAML::Node n = get(key);
  std::vector<YamlReader> out;
  if (!n.IsDefined() || n.IsNull()) return out;
  if (!n.IsSequence()) fail(key, "expected a list (got " + shown(n) + ")");
  for (size_t i = 0; i < n.size(); ++i) {
    YamlReader item(n[i], file_, keyPath(key) + "[" + std::to_string(i) + "]");
    item.checkMap();
    out.push_back(item);
  }
  return out;
}

void YamlReader::finish() const {
  checkMap();
  if (!node_.IsMap()) return;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.Scalar();  // checkMap: every key is a scalar
    if (std::find(known_.begin(), known_.end(), k) != known_.end()) continue;
    std::string expected, suggestion;
    for (const auto& e : known_) {
      expected += (expected.empty() ? "" : ", ") + e;
      if (suggestion.empty() && nearMiss(k, e)) suggestion = " (did you mean " + e + "?)";
    }
    YAML::Mark m = it->first.Mark();
    throw ConfigError(file_, m.is_null() ? 1 : m.line + 1, "",
                      "unknown key '" + clip(k) + "' in " + (path_.empty() ? std::string("<document>") : path_) +
                          suggestion + "; expected one of " + (expected.empty() ? "(none)" : expected));
  }
}

}  // namespace common::config
