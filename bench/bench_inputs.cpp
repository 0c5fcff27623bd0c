// Seconds to accept or refuse pathological inputs of 1, 3 and 10 MB (and
// 0.25 MB, the YAML loaders' size limit), per loader: the URDF (RobotModel),
// the field, a scenario and an experiment. The speed issue asks for any
// input up to 10 MB to be accepted or refused in under a second; a loader
// that is not linear in its input shows up here (a 3 MB URDF with a NUL
// byte near its end once took 33 s).
//
// Each input is generated from the shipped file, written to a temporary
// folder and loaded through the same file loader the simswift program uses.
//
// Usage: bench_inputs [FILTER] [--sizes 0.25,1,3,10]
//   FILTER: only cases whose name contains it (e.g. "urdf", "many_lines");
//   --sizes: input sizes in MB (MiB; fractions allowed, e.g. 0.25 to see
//   how a case scales);
//   --keep DIR: write the inputs into DIR and keep them (to replay one
//   with the simswift program).
// Figures are printed and appended to the results file (see
// bench/BenchResults.hpp) as inputs.<loader>.<case>_<size>mb.seconds.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "BenchResults.hpp"
#include "app/experiment/Experiment.hpp"
#include "sim/nao_model/RobotModel.hpp"
#include "sim/runner/Scenario.hpp"
#include "sim/world/ConfigError.hpp"
#include "sim/world/FieldConfig.hpp"

using namespace simswift;

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Comment lines of `width` bytes (newline included) until `s` holds `size`
// bytes; `open`/`close` wrap each line ("# ", "" for YAML; the URDF pads
// inside one comment).
void padLines(std::string& s, size_t size, size_t width, const std::string& open) {
  const std::string line = open + std::string(width > open.size() + 1 ? width - open.size() - 1 : 1, 'x') + "\n";
  while (s.size() + line.size() <= size) s += line;
}

// ---- URDF ---------------------------------------------------------------

const std::string& urdfSeed() {
  static const std::string s = readText(SIMSWIFT_SOURCE_DIR "/models/nao_v5.urdf");
  return s;
}

// Inserts `body` just before </robot>.
std::string urdfWith(const std::string& body) {
  std::string xml = urdfSeed();
  xml.insert(xml.rfind("</robot>"), body);
  return xml;
}

// Comment lines, then a link whose name holds a NUL byte (the fuzzer's case).
std::string urdfNulNearEnd(size_t size) {
  std::string pad = "<!--\n";
  padLines(pad, size - urdfSeed().size() - 64, 72, "");
  pad += "-->\n<link name=\"bad";
  pad += '\0';
  pad += "\"/>\n";
  return urdfWith(pad);
}

// The whole document on one line, the <robot> element carrying one huge
// attribute value (urdfdom ignores unknown attributes).
std::string urdfOneLongLine(size_t size) {
  std::string xml = urdfSeed();
  for (char& c : xml)
    if (c == '\n') c = ' ';
  const size_t at = xml.find("<robot") + 6;
  xml.insert(at, " doc=\"" + std::string(size > xml.size() + 8 ? size - xml.size() - 8 : 1, 'x') + "\"");
  return xml;
}

// Blank lines between the elements.
std::string urdfManyLines(size_t size) { return urdfWith(std::string(size - urdfSeed().size(), '\n')); }

// Valid-looking links, each hung on the head by a revolute joint.
std::string urdfManyElements(size_t size) {
  std::string body;
  for (int k = 0; urdfSeed().size() + body.size() < size; ++k) {
    const std::string n = std::to_string(k);
    body += "<link name=\"extra" + n +
            "\">\n  <inertial><origin xyz=\"0 0 0\" rpy=\"0 0 0\"/><mass value=\"0.01\"/>\n"
            "  <inertia ixx=\"1e-6\" ixy=\"0\" ixz=\"0\" iyy=\"1e-6\" iyz=\"0\" izz=\"1e-6\"/></inertial>\n"
            "  <collision><origin xyz=\"0 0 0\" rpy=\"0 0 0\"/><geometry><box size=\"0.01 0.01 0.01\"/></geometry></collision>\n"
            "</link>\n<joint name=\"extra_joint" + n +
            "\" type=\"revolute\">\n  <parent link=\"Head\"/><child link=\"extra" + n +
            "\"/>\n  <origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1\"/>\n"
            "  <limit lower=\"-1\" upper=\"1\" velocity=\"1\" effort=\"1\"/>\n</joint>\n";
  }
  return urdfWith(body);
}

// One element with a great many attributes (the XML parser looks each new
// attribute up among the ones before it).
std::string urdfManyAttributes(size_t size) {
  std::string xml = urdfSeed();
  std::string attrs;
  for (int k = 0; xml.size() + attrs.size() < size; ++k) attrs += " a" + std::to_string(k) + "=\"0\"";
  xml.insert(xml.find("<robot") + 6, attrs);
  return xml;
}

// Elements nested ever deeper, each on its own line.
std::string urdfDeepNesting(size_t size) {
  std::string open, close;
  while (urdfSeed().size() + open.size() + close.size() + 8 < size) {
    open += "<a>\n";
    close += "</a>";
  }
  return urdfWith(open + close);
}

// ---- YAML ---------------------------------------------------------------

const std::string& fieldSeed() {
  static const std::string s = readText(SIMSWIFT_SOURCE_DIR "/fields/spl_2017.yaml");
  return s;
}
const std::string& scenarioSeed() {
  static const std::string s = readText(SIMSWIFT_SOURCE_DIR "/scenarios/stand_one.yaml");
  return s;
}
const std::string& experimentSeed() {
  static const std::string s = readText(SIMSWIFT_SOURCE_DIR "/scenarios/sweep_quick.yaml");
  return s;
}

std::string yamlNulNearEnd(const std::string& seed, size_t size) {
  std::string s = seed + "\n";
  padLines(s, size - 16, 72, "# ");
  s += "# a NUL: ";
  s += '\0';
  s += "\n";
  return s;
}

// One line: an unknown key `size` bytes long.
std::string yamlOneLongLine(const std::string& seed, size_t size) {
  return seed + "\n" + std::string(size > seed.size() + 8 ? size - seed.size() - 8 : 1, 'k') + ": 1\n";
}

std::string yamlManyLines(const std::string& seed, size_t size) {
  std::string s = seed + "\n";
  while (s.size() + 2 <= size) s += "#\n";
  return s;
}

// A flow list nested `size` / 2 deep under an unknown key.
std::string yamlDeepNesting(const std::string& seed, size_t size) {
  const size_t depth = (size - seed.size()) / 2 - 8;
  return seed + "\ndeep: " + std::string(depth, '[') + std::string(depth, ']') + "\n";
}

// A map of distinct unknown keys where the loader looks its keys up: under
// `indent` after the seed, or at the top before it ("").
std::string yamlManyKeys(const std::string& seed, size_t size, const std::string& indent) {
  std::string keys;
  for (int k = 0;; ++k) {
    const std::string key = indent + "key" + std::to_string(k) + ": 1\n";
    if (seed.size() + keys.size() + key.size() + 1 > size) break;
    keys += key;
  }
  return indent.empty() ? keys + seed : seed + "\n" + keys;
}

// A field with a great many (valid) lines.
std::string fieldHugeList(size_t size) {
  std::string s = fieldSeed();
  std::string lines;
  const size_t at = s.find("  lines:");
  const size_t end = s.find('\n', at) + 1;
  for (int k = 0;; ++k) {
    const std::string line = "    - {name: l" + std::to_string(k) + ", from: [-4.5, 0.5], to: [4.5, 0.5], width: 0.05}\n";
    if (s.size() + lines.size() + line.size() > size) break;
    lines += line;
  }
  s.insert(end, lines);
  return s;
}

// A scenario whose game timeline has a great many (valid, ordered) entries.
std::string scenarioHugeList(size_t size) {
  std::string s = scenarioSeed() + "game:\n  timeline:\n";
  for (int k = 0;; ++k) {
    const std::string entry = "    - {t: " + std::to_string(k) + ", state: playing}\n";
    if (s.size() + entry.size() > size) break;
    s += entry;
  }
  return s;
}

// An experiment with a great many (valid) setups.
std::string experimentHugeList(size_t size) {
  std::string s = experimentSeed();
  const size_t at = s.find("setups:\n") + 8;
  std::string setups;
  for (int k = 0;; ++k) {
    const std::string setup = "  - {name: s" + std::to_string(k) +
                              ", behaviour: findball2017, robots: [{team: 19, player: 2, x: -3.25, y: 3.0, theta: 0}]}\n";
    if (s.size() + setups.size() + setup.size() > size) break;
    setups += setup;
  }
  s.insert(at, setups);
  return s;
}

// The shipped sweep with 1,000 values on one axis, padded with comments to
// `size`: every cell is checked in full.
std::string experimentBigSweep(size_t size) {
  std::string s = experimentSeed();
  const size_t at = s.find("  team_comms.loss:");
  s.erase(at, s.find('\n', at) + 1 - at);
  s.erase(s.find("  vision.ball.max_distance_mm:"));
  std::string values = "  team_comms.loss: [0";
  for (int k = 1; k < 1000; ++k) values += ", " + std::to_string(k / 1000.0);
  s += values + "]\n";
  padLines(s, size, 72, "# ");
  return s;
}

// The shipped sweep with a great many one-value axes (one cell): every
// pair of paths is checked for overlap.
std::string experimentManyAxes(size_t size) {
  std::string s = experimentSeed();
  s.erase(s.find("  team_comms.loss:"));
  for (int k = 0;; ++k) {
    const std::string axis = "  setups.2017.config.k" + std::to_string(k) + ": [1]\n";
    if (s.size() + axis.size() > size) break;
    s += axis;
  }
  return s;
}

// ---- running ------------------------------------------------------------

struct Case {
  std::string loader;  // urdf, field, scenario, experiment
  std::string name;
  std::function<std::string(size_t)> make;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"urdf", "nul_near_end", urdfNulNearEnd});
  c.push_back({"urdf", "one_long_line", urdfOneLongLine});
  c.push_back({"urdf", "many_lines", urdfManyLines});
  c.push_back({"urdf", "many_elements", urdfManyElements});
  c.push_back({"urdf", "many_attributes", urdfManyAttributes});
  c.push_back({"urdf", "deep_nesting", urdfDeepNesting});
  struct Yaml {
    const char* loader;
    const std::string& (*seed)();
    const char* key_indent;  // where many_keys puts its keys
    std::function<std::string(size_t)> huge_list;
  };
  for (const Yaml& y : {Yaml{"field", fieldSeed, "  ", fieldHugeList}, Yaml{"scenario", scenarioSeed, "", scenarioHugeList},
                        Yaml{"experiment", experimentSeed, "", experimentHugeList}}) {
    auto seed = y.seed;
    const std::string indent = y.key_indent;
    c.push_back({y.loader, "nul_near_end", [seed](size_t n) { return yamlNulNearEnd(seed(), n); }});
    c.push_back({y.loader, "one_long_line", [seed](size_t n) { return yamlOneLongLine(seed(), n); }});
    c.push_back({y.loader, "many_lines", [seed](size_t n) { return yamlManyLines(seed(), n); }});
    c.push_back({y.loader, "deep_nesting", [seed](size_t n) { return yamlDeepNesting(seed(), n); }});
    c.push_back({y.loader, "many_keys", [seed, indent](size_t n) { return yamlManyKeys(seed(), n, indent); }});
    c.push_back({y.loader, "huge_list", y.huge_list});
  }
  c.push_back({"experiment", "big_sweep", experimentBigSweep});
  c.push_back({"experiment", "many_axes", experimentManyAxes});
  return c;
}

// Loads `path` with the loader's file reader; the outcome in `*what`.
void load(const std::string& loader, const std::string& path, std::string* what) {
  try {
    if (loader == "urdf") {
      RobotModel::loadUrdf(path);
    } else if (loader == "field") {
      FieldConfig::loadYaml(path);
    } else if (loader == "scenario") {
      runner::Scenario::loadFile(path);
    } else {
      experiment::Experiment::loadFile(path);
    }
    *what = "accepted";
  } catch (const std::exception& e) {
    *what = std::string("refused: ") + e.what();
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string filter;
  // 0.25 MB: the YAML loaders' size limit (the largest YAML input accepted).
  std::vector<double> sizes_mb = {0.25, 1, 3, 10};
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--keep") == 0 && i + 1 < argc) {
      keep = argv[++i];
      continue;
    }
    if (std::strcmp(argv[i], "--sizes") == 0 && i + 1 < argc) {
      sizes_mb.clear();
      std::istringstream in(argv[++i]);
      for (std::string v; std::getline(in, v, ',');) sizes_mb.push_back(std::atof(v.c_str()));
    } else {
      filter = argv[i];
    }
  }
  // Shipped files name models/ and fields/ relative to the data folder.
  setenv("SIMSWIFT_DATA_DIR", SIMSWIFT_SOURCE_DIR, 0);
  char tmpl[] = "/tmp/bench_inputs_XXXXXX";
  if (!mkdtemp(tmpl)) {
    std::perror("mkdtemp");
    return 1;
  }
  const std::string dir = keep.empty() ? std::string(tmpl) : keep;
  if (!keep.empty()) std::filesystem::create_directories(keep);
  std::printf("simswift input benchmark: seconds to accept or refuse each input (file loaders, one core)\n");
  double worst = 0;
  std::string worst_name;
  for (const Case& c : cases()) {
    for (double mb : sizes_mb) {
      char label[32];
      std::snprintf(label, sizeof label, "_%gmb", mb);
      const std::string name = "inputs." + c.loader + "." + c.name + label;
      if (!filter.empty() && name.find(filter) == std::string::npos) continue;
      const size_t size = static_cast<size_t>(mb * (1 << 20));  // MiB
      const std::string path =
          dir + "/" + c.loader + "_" + c.name + (keep.empty() ? "" : label) + (c.loader == "urdf" ? ".urdf" : ".yaml");
      {
        std::ofstream out(path, std::ios::binary);
        const std::string text = c.make(size);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
      }
      std::string what;
      const auto t0 = std::chrono::steady_clock::now();
      load(c.loader, path, &what);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      bench::report(name + ".seconds", s, "s");
      std::printf("    %s\n", what.substr(0, 160).c_str());
      if (s > worst) {
        worst = s;
        worst_name = name;
      }
      if (keep.empty()) std::filesystem::remove(path);
    }
  }
  std::filesystem::remove_all(tmpl);
  std::printf("slowest: %s %.3f s (target: every input under 1 s)\n", worst_name.c_str(), worst);
  return 0;
}
