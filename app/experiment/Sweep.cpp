#include "app/experiment/Sweep.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace simswift::experiment {

namespace {

// The scenario settings an experiment takes as its base (Experiment.cpp
// reads them with the scenario's readers).
const std::vector<std::string> kSettings = {"team_comms", "game", "vision", "noise", "physics"};

const char* kSweepable =
    "sweepable paths: team_comms.<key>, game.<key>, vision.<...>, noise or noise.<key>, physics.<key>, "
    "setups.<name or index>.config.<...>, setups.<name or index>.robots.<index>.config.<...>";

int lineOf(const YAML::Node& n) { return n.Mark().is_null() ? 1 : n.Mark().line + 1; }

std::vector<std::string> splitPath(const std::string& p) {
  std::vector<std::string> out(1);
  for (char c : p) {
    if (c == '.') out.emplace_back();
    else out.back() += c;
  }
  return out;
}

std::string joinPath(const std::vector<std::string>& seg, size_t n) {
  std::string s;
  for (size_t i = 0; i < n && i < seg.size(); ++i) s += (i ? "." : "") + seg[i];
  return s;
}

bool allDigits(const std::string& s) {
  return !s.empty() && s.size() < 7 && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::string label(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << v;
  return e.c_str();
}

std::string kindOf(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "empty";
}

// What a ConfigError says after its "file:line: " (the line is replaced).
std::string afterWhere(const std::string& file, const std::string& what) {
  if (what.rfind(file + ":", 0) != 0) return what;
  size_t k = file.size() + 1;
  while (k < what.size() && std::isdigit(static_cast<unsigned char>(what[k]))) ++k;
  if (what.compare(k, 2, ": ") == 0) return what.substr(k + 2);
  return what;
}

// A fresh copy of map entry `key` of `parent` put in its place: changes
// below it reach no node the file shares through an alias. (Assigning to
// the entry itself would write through to every alias.)
YAML::Node ownCopy(YAML::Node parent, const std::string& key) {
  YAML::Node fresh = YAML::Clone(parent[key]);
  parent.remove(key);
  parent[key] = fresh;
  return fresh;
}

}  // namespace

std::vector<SweepAxis> readSweep(const YamlReader& top) {
  const YAML::Node sweep = top.node()["sweep"];
  if (!sweep.IsMap() || sweep.size() == 0)
    top.fail("sweep", "must be a map of setting paths to lists of values, e.g. team_comms.loss: [0, 0.1]");
  std::vector<SweepAxis> axes;
  const std::string file = top.file();
  (void)YamlReader(sweep, file, "sweep").keys();  // a list or map as a path: refused at its line
  for (const auto& kv : sweep) {
    if (axes.size() == static_cast<size_t>(kMaxSweepPaths))
      throw ConfigError(file, lineOf(kv.first), "sweep", "more than " + std::to_string(kMaxSweepPaths) +
                        " paths (1000 cells allow 9 with two values or more; a setting with one value belongs in "
                        "the experiment itself)");
    SweepAxis a;
    a.path = kv.first.Scalar();
    a.line = kv.first.Mark().is_null() ? 1 : kv.first.Mark().line + 1;
    const std::string key = "sweep." + a.path;
    for (const std::string& s : splitPath(a.path))
      if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
          }))
        throw ConfigError(file, a.line, key,
                          std::string("not a dotted path of keys (letters, digits, _ and -; ") + kSweepable + ")");
    const YAML::Node list = kv.second;
    if (!list.IsSequence())
      throw ConfigError(file, a.line, key, "must be a list of values (got " + kindOf(list) + "; one value: [" +
                        (list.IsScalar() ? list.Scalar() : std::string("...")) + "])");
    if (list.size() == 0) throw ConfigError(file, a.line, key, "an empty list: give at least one value");
    std::set<std::string> seen;
    for (const YAML::Node& v : list) {
      SweepValue sv;
      sv.label = label(v);
      sv.line = lineOf(v);
      if (!seen.insert(sv.label).second)
        throw ConfigError(file, sv.line, key, "value " + sv.label + " appears twice");
      a.values.push_back(sv);
    }
    for (const SweepAxis& b : axes) {
      const bool overlap = a.path == b.path || a.path.rfind(b.path + ".", 0) == 0 || b.path.rfind(a.path + ".", 0) == 0;
      if (overlap) throw ConfigError(file, a.line, key, "overlaps sweep path " + b.path + " (line " + std::to_string(b.line) + ")");
    }
    axes.push_back(std::move(a));
  }
  // The cell count, stopping once past the cap (no overflow).
  long long cells = 1;
  std::string dims;
  for (const SweepAxis& a : axes) {
    cells = std::min<long long>(cells * static_cast<long long>(a.values.size()), kMaxSweepCells + 1LL);
    dims += (dims.empty() ? "" : " x ") + std::to_string(a.values.size());
  }
  if (cells > kMaxSweepCells) {
    int line = 1;  // of the sweep: key (its map's mark is the line below)
    for (const auto& kv : top.node())
      if (kv.first.IsScalar() && kv.first.Scalar() == "sweep" && !kv.first.Mark().is_null()) line = kv.first.Mark().line + 1;
    throw ConfigError(file, line, "sweep", "more than " + std::to_string(kMaxSweepCells) + " cells (" + dims +
                      " value combinations); sweep fewer values or split the file");
  }
  return axes;
}

int sweepCells(const std::vector<SweepAxis>& axes) {
  int n = 1;
  for (const SweepAxis& a : axes) n *= static_cast<int>(a.values.size());
  return n;
}

std::vector<int> sweepChoice(const std::vector<SweepAxis>& axes, int cell) {
  std::vector<int> choice(axes.size(), 0);
  for (size_t k = axes.size(); k-- > 0;) {
    const int n = static_cast<int>(axes[k].values.size());
    choice[k] = cell % n;
    cell /= n;
  }
  return choice;
}

std::string cellLabel(const std::vector<SweepAxis>& axes, int cell) {
  const std::vector<int> c = sweepChoice(axes, cell);
  std::string s;
  for (size_t k = 0; k < axes.size(); ++k)
    s += (k ? ", " : "") + axes[k].path + "=" + axes[k].values[c[k]].label;
  return s;
}

void applySweepValue(YAML::Node root, const SweepAxis& axis, int value, const std::string& file) {
  const std::vector<std::string> seg = splitPath(axis.path);
  auto fail = [&](const std::string& why) {
    throw ConfigError(file, axis.line, "sweep." + axis.path, why);
  };
  const YAML::Node v = root["sweep"][axis.path][value];
  // `at`: the map the rest of the path (from seg[next]) walks down.
  YAML::Node at;
  size_t next = 0;
  if (std::find(kSettings.begin(), kSettings.end(), seg[0]) != kSettings.end()) {
    at.reset(root);
    if (seg.size() > 1) {
      const YAML::Node block = root[seg[0]];
      if (block.IsDefined() && !block.IsNull() && !block.IsMap())
        fail("'" + seg[0] + "' is " + kindOf(block) + " in the experiment, not a map: it has no key '" + seg[1] + "'");
      if (block.IsDefined() && block.IsMap()) {
        at.reset(ownCopy(root, seg[0]));
        next = 1;
      }
    }
  } else if (seg[0] == "setups") {
    YAML::Node setups = root["setups"];
    if (seg.size() < 3 || !(seg[2] == "config" || (seg[2] == "robots" && seg.size() >= 5 && seg[4] == "config")))
      fail(std::string("a setup's sweepable part is its behaviour overrides: ") +
           "setups.<name or index>.config.<...> or setups.<name or index>.robots.<index>.config.<...>");
    if (!setups.IsSequence()) fail("the experiment has no setups: list");
    int index = -1;
    std::string names;
    for (size_t i = 0; i < setups.size(); ++i) {
      const YAML::Node n = setups[i]["name"];
      const std::string name = n.IsScalar() ? n.Scalar() : "";
      names += (i ? ", " : "") + name;
      if (name == seg[1] && index < 0) index = static_cast<int>(i);
    }
    if (index < 0 && allDigits(seg[1]) && std::stoi(seg[1]) < static_cast<int>(setups.size())) index = std::stoi(seg[1]);
    if (index < 0) fail("no setup '" + seg[1] + "' (setups: " + names + "; or an index from 0)");
    // A new setups list in the file's place, holding the same setups but a
    // copy of this one (a robots list shared by alias stays unchanged in the
    // other setups): no node of the file's tree changes, so SweepTree can put
    // it back. The list is made as root's own entry: yaml-cpp copies the node
    // set of what is assigned into a node into that node's set, so building
    // it as a fresh node would copy the whole file's set each time.
    const YAML::Node old = setups;
    const YAML::Node fresh = YAML::Clone(old[index]);
    root.remove("setups");
    YAML::Node list = root["setups"];
    for (size_t i = 0; i < old.size(); ++i) list.push_back(static_cast<int>(i) == index ? fresh : old[i]);
    at.reset(fresh);
    next = 2;
    if (seg[2] == "robots") {
      const YAML::Node robots = fresh["robots"];
      const int n = robots.IsSequence() ? static_cast<int>(robots.size()) : 0;
      if (!allDigits(seg[3]) || std::stoi(seg[3]) >= n)
        fail("no robot '" + seg[3] + "' in setup '" + seg[1] + "' (robots are numbered 0.." + std::to_string(n - 1) +
             " in its robots: list)");
      at.reset(robots[std::stoi(seg[3])]);
      next = 4;
    }
  } else {
    fail(std::string("unknown path (") + kSweepable + ")");
  }
  // Down the maps (created where the base has none), then the value.
  for (size_t k = next; k + 1 < seg.size(); ++k) {
    YAML::Node child = at[seg[k]];
    if (!child.IsDefined() || child.IsNull()) {
      at.remove(seg[k]);  // a new entry: assigning to a null one would change the file's node
      at[seg[k]] = YAML::Node(YAML::NodeType::Map);
    } else if (!child.IsMap()) {
      fail("'" + joinPath(seg, k + 1) + "' is " + kindOf(child) + " in the experiment, not a map: it has no key '" +
           seg[k + 1] + "'");
    }
    at.reset(at[seg[k]]);
  }
  if (at[seg.back()].IsDefined()) at.remove(seg.back());  // replaced, not written through an alias
  at[seg.back()] = v;
}

SweepTree::SweepTree(YAML::Node root) : root_(root) {
  const YAML::Node& c = root_;  // const: never inserts
  for (const std::string& key : kSettings) saved_.emplace_back(key, c[key]);
  saved_.emplace_back("setups", c["setups"]);
}

void SweepTree::apply(const SweepAxis& axis, int value, const std::string& file) {
  applySweepValue(root_, axis, value, file);
}

void SweepTree::restore() {
  for (const auto& [key, node] : saved_) {
    root_.remove(key);
    if (node.IsDefined()) root_[key] = node;
  }
}

ConfigError blameValue(const std::string& file, const SweepAxis& axis, int value, const std::string& what) {
  const SweepValue& v = axis.values[value];
  const std::string key = "sweep." + axis.path + "[" + std::to_string(value) + "]";
  ConfigError e(file, v.line, key + " = " + v.label, afterWhere(file, what));
  e.key = key;  // the value's path; the message shows the value too
  return e;
}

ConfigError blameCell(const std::string& file, int sweep_line, const std::vector<SweepAxis>& axes, int cell,
                      const std::string& what) {
  return ConfigError(file, sweep_line, "sweep",
                     "cell " + std::to_string(cell) + " (" + cellLabel(axes, cell) + "): " + afterWhere(file, what));
}

}  // namespace simswift::experiment
