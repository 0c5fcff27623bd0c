#include "app/scenario_tests/TestFile.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/config/Seed.hpp"
#include "common/random/DeriveSeed.hpp"
#include "common/random/Random.hpp"
#include "app/experiment/Statistics.hpp"

namespace simswift::scenario_tests {

using common::config::Range;
using common::config::YamlReader;

namespace {

constexpr int kMaxSeeds = 100000;
constexpr double kMaxTimeLimit = 3600;  // s of simulated time per run

std::string flowYaml(const YAML::Node& n) {
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

// What a test measures, as flow YAML: its entry without what may change
// while a baseline stays comparable (its name, seed counts and required
// rate; its robots' programs and behaviours: the program under test).
std::string measuredPart(const YAML::Node& test) {
  YAML::Node t = YAML::Clone(test);
  for (const char* k : {"name", "seeds", "short", "required"}) t.remove(k);
  YAML::Node sc = t["scenario"];
  if (sc.IsMap() && sc["robots"] && sc["robots"].IsSequence())
    for (YAML::Node r : sc["robots"])
      if (r.IsMap()) {
        r.remove("behaviour");
        r.remove("program");
      }
  return flowYaml(t);
}

using Defaults = TestDefaults;

// The least seed count at which every run passing confirms `required` (the
// Wilson lower end of n/n reaches it: the very test checkConfirmable
// applies, searched upward one by one), or 0 if none up to kMaxSeeds does.
// (n/n's lower end is n / (n + z^2), so this is ceil(z^2 r / (1 - r)): 73
// for 0.95; the search keeps it the same test, rounding and all.)
int seedsToConfirm(double required) {
  for (int n = 1; n <= kMaxSeeds; ++n)
    if (experiment::stats::wilson(n, n).lo >= required) return n;
  return 0;
}

// Refuses a required rate that the test's seeds cannot confirm.
void checkConfirmable(const YamlReader& t, const ScenarioTest& test) {
  if (test.required >= 1)
    t.fail("required", "a rate of 1 can never be confirmed (a 95 % interval's lower end stays below 1): use a rate "
                       "below 1, e.g. 0.95");
  for (const int n : {test.seeds, test.short_seeds}) {
    const double lo = experiment::stats::wilson(n, n).lo;
    if (lo < test.required)
      t.fail(t.has("required") ? "required" : "seeds",
             "with " + std::to_string(n) + " seeds even " + std::to_string(n) + "/" + std::to_string(n) +
                 " passes give a 95 % lower bound of " + std::to_string(lo).substr(0, 5) + ", below the required " +
                 std::to_string(test.required).substr(0, 5) + ": the test could never pass; " +
                 (seedsToConfirm(test.required) > 0
                      ? "use at least " + std::to_string(seedsToConfirm(test.required)) + " seeds" +
                            (n == test.short_seeds && n != test.seeds ? " in short:" : "") + " or a lower rate"
                      : "no seed count up to " + std::to_string(kMaxSeeds) + " can: use a lower rate"));
  }
}

// A fuzz range: a number a (>= 0) for [-a, a], or offsets [lo, hi].
Range2 readRange(const YamlReader& r, const std::string& key, double max) {
  Range2 out;
  if (!r.has(key)) return out;
  const YAML::Node n = r.node()[key];
  if (n.IsSequence()) {
    const std::vector<double> v = r.numbers(key, 2, Range::closed(-max, max));
    if (v[0] > v[1]) r.fail(key, "must be [low, high] with low <= high");
    out.lo = v[0];
    out.hi = v[1];
  } else {
    const double a = r.number(key, Range::closed(0, max));
    out.lo = -a;
    out.hi = a;
  }
  return out;
}

PoseFuzz readPoseFuzz(const YamlReader& r, bool theta) {
  PoseFuzz f;
  f.x = readRange(r, "x", 10);
  f.y = readRange(r, "y", 10);
  if (theta) f.theta = readRange(r, "theta", 2 * M_PI);
  r.finish();
  return f;
}

void readFuzz(const YamlReader& t, ScenarioTest& test) {
  test.robot_fuzz.assign(test.scenario.robots.size(), PoseFuzz{});
  const auto f = t.optionalMap("fuzz");
  if (!f) return;
  if (f->has("robots")) {
    if (f->node()["robots"].IsSequence()) {
      const std::vector<YamlReader> list = f->list("robots");
      if (list.size() > test.scenario.robots.size())
        f->fail("robots", "lists " + std::to_string(list.size()) + " robots; the scenario has " +
                              std::to_string(test.scenario.robots.size()));
      for (size_t i = 0; i < list.size(); ++i) test.robot_fuzz[i] = readPoseFuzz(list[i], true);
    } else {
      const PoseFuzz all = readPoseFuzz(f->map("robots"), true);
      for (PoseFuzz& p : test.robot_fuzz) p = all;
    }
  }
  if (auto b = f->optionalMap("ball")) {
    if (test.scenario.no_ball) b->fail("the scenario has no ball (ball: none)");
    test.ball_fuzz = readPoseFuzz(*b, false);
  }
  f->finish();
}

void readScenario(const YamlReader& t, const std::string& source, ScenarioTest& test) {
  if (!t.has("scenario")) t.missing("scenario", "required: a scenario map or a scenario file's name");
  const YAML::Node n = t.node()["scenario"];
  if (n.IsScalar()) {
    const std::string name = t.string("scenario");
    std::filesystem::path p(name);
    if (p.is_relative()) p = std::filesystem::path(source).parent_path() / p;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) t.fail("scenario", "no scenario file " + p.string());
    test.scenario = runner::Scenario::loadFile(p.string());
  } else {
    test.scenario = runner::Scenario::read(t.map("scenario"), source);
  }
  if (test.scenario.robots.empty()) t.fail("scenario", "has no robots: a test needs at least one");
  if (test.scenario.camera.any()) t.fail("scenario", "renders cameras: a test runs without (leave camera: out)");
}

ScenarioTest readTest(const YamlReader& t, const std::string& source, const Defaults& d,
                      std::set<std::string>& names) {
  ScenarioTest test;
  test.line = t.node().Mark().line + 1;
  test.definition = measuredPart(t.node());
  test.name = t.string("name");
  if (test.name.empty() || test.name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") !=
                               std::string::npos)
    t.fail("name", "must be letters, digits, '_', '.' or '-' (got '" + test.name + "')");
  if (!names.insert(test.name).second) t.fail("name", "a second test named " + test.name);
  test.seeds = t.integer("seeds", d.seeds, Range::closed(1, kMaxSeeds));
  test.short_seeds = test.seeds;
  if (auto s = t.optionalMap("short")) {
    test.short_seeds = s->integer("seeds", Range::closed(1, kMaxSeeds));
    s->finish();
  }
  test.time_limit = t.number("time_limit", d.time_limit, Range::openClosed(0, kMaxTimeLimit));
  test.required = t.number("required", d.required, Range::openClosed(0, 1));
  checkConfirmable(t, test);
  readScenario(t, source, test);
  test.scenario.duration = test.time_limit;
  test.field = FieldConfig::loadYaml(test.scenario.fieldFile());
  readFuzz(t, test);
  test.pass = readCondition(t, "pass", static_cast<int>(test.scenario.robots.size()), test.time_limit);
  t.finish();
  return test;
}

uint64_t fnv1a(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

double draw(common::random::Random& rng, const Range2& r) { return r.any() ? rng.uniform(r.lo, r.hi) : 0.0; }

}  // namespace

TestFile TestFile::loadFile(const std::string& path) { return parse(YamlReader::readFile(path, "test file"), path); }

TestFile TestFile::parse(const std::string& text, const std::string& source_name) {
  const YAML::Node root = YamlReader::parse(text, source_name);
  YamlReader top(root, source_name);
  TestFile f;
  f.source = source_name;
  f.text = text;
  f.name = top.string("name");
  if (f.name.empty() || f.name.find('/') != std::string::npos) top.fail("name", "must be a name without '/'");
  f.seed = common::config::readSeed(top, "seed", f.seed);  // all 64 bits, exact (not a YAML number)
  Defaults d;
  if (auto dm = top.optionalMap("defaults")) {
    d.seeds = dm->integer("seeds", d.seeds, Range::closed(1, kMaxSeeds));
    d.required = dm->number("required", d.required, Range::openClosed(0, 1));
    d.time_limit = dm->number("time_limit", d.time_limit, Range::openClosed(0, kMaxTimeLimit));
    dm->finish();
  }
  if (!top.has("tests")) top.missing("tests", "required: a list of tests");
  const std::vector<YamlReader> tests = top.list("tests");
  if (tests.empty()) top.fail("tests", "needs at least one test");
  std::set<std::string> names;
  int64_t runs = 0;
  for (const YamlReader& t : tests) {
    f.tests.push_back(readTest(t, source_name, d, names));
    runs += std::max(f.tests.back().seeds, f.tests.back().short_seeds);
    if (runs > kMaxRuns)
      t.fail("seeds", "the file asks for more than " + std::to_string(kMaxRuns) + " runs in all");
  }
  top.finish();
  return f;
}

std::map<std::string, std::string> testDefinitions(const std::string& text, const std::string& source) {
  const YAML::Node root = YamlReader::parse(text, source);
  std::map<std::string, std::string> out;
  if (!root.IsMap() || !root["tests"] || !root["tests"].IsSequence())
    throw ConfigError(source + ":1: not a test file (no tests: list)");
  for (const YAML::Node& t : root["tests"])
    if (t.IsMap() && t["name"] && t["name"].IsScalar()) out[t["name"].Scalar()] = measuredPart(t);
  return out;
}

bool selectTests(TestFile& f, const std::string& names, std::string* error) {
  std::set<std::string> wanted;
  std::stringstream in(names);
  std::string n;
  while (std::getline(in, n, ','))
    if (!n.empty()) wanted.insert(n);
  for (const std::string& w : wanted) {
    bool found = false;
    for (const ScenarioTest& t : f.tests) found = found || t.name == w;
    if (!found) {
      *error = "no test named " + w + " in " + f.source;
      return false;
    }
  }
  std::vector<ScenarioTest> kept;
  for (ScenarioTest& t : f.tests)
    if (wanted.count(t.name)) kept.push_back(std::move(t));
  f.tests = std::move(kept);
  if (f.tests.empty()) *error = "names no test";
  return !f.tests.empty();
}

uint64_t runSeed(uint64_t file_seed, const std::string& test, int run) {
  // The test's name is the tag, so adding or reordering tests moves no
  // other test's seeds; 31 bits, as trial seeds (RunSpec::seed).
  using common::random::deriveSeed;
  return deriveSeed(deriveSeed(file_seed, fnv1a(test)), static_cast<uint64_t>(run)) % 2147483647ull;
}

int countRuns(const TestFile& f, bool short_form) {
  int n = 0;
  for (const ScenarioTest& t : f.tests) n += short_form ? t.short_seeds : t.seeds;
  return n;
}

RunSpec runSpec(const TestFile& f, bool short_form, int index, uint64_t seed_override, bool has_override) {
  RunSpec s;
  s.index = index;
  int left = index;
  for (size_t k = 0; k < f.tests.size(); ++k) {
    const int n = short_form ? f.tests[k].short_seeds : f.tests[k].seeds;
    if (left < n) {
      s.test = static_cast<int>(k);
      s.run = left;
      s.seed = runSeed(has_override ? seed_override : f.seed, f.tests[k].name, left);
      return s;
    }
    left -= n;
  }
  throw std::out_of_range("run index " + std::to_string(index));
}

runner::Scenario runScenario(const ScenarioTest& t, uint64_t seed) {
  runner::Scenario sc = t.scenario;
  sc.seed = seed;
  // The fuzz's own stream: its draws do not depend on anything the run draws.
  common::random::Random rng(common::random::deriveSeed(seed, common::random::seed_tag::kPlacementFuzz));
  for (size_t i = 0; i < sc.robots.size(); ++i) {
    const PoseFuzz& f = t.robot_fuzz[i];
    sc.robots[i].x += draw(rng, f.x);
    sc.robots[i].y += draw(rng, f.y);
    sc.robots[i].theta += draw(rng, f.theta);
  }
  if (t.ball_fuzz.x.any() || t.ball_fuzz.y.any()) {
    auto ball = sc.ball.value_or(std::make_pair(0.0, 0.0));
    ball.first += draw(rng, t.ball_fuzz.x);
    ball.second += draw(rng, t.ball_fuzz.y);
    sc.ball = ball;
  }
  return sc;
}

}  // namespace simswift::scenario_tests
