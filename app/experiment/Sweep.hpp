// An experiment's `sweep:`: settings of the base experiment given several
// values by dotted path; every combination of values is a cell, run as the
// whole experiment (every setup x ball position x trial):
//
//   sweep:
//     team_comms.loss: [0, 0.1, 0.3]
//     vision.ball.max_distance_mm: [1500, 2500, 3500]
//     setups.2017.config.search.spin_at_point: [on, off]
//
// Sweepable: the scenario settings an experiment takes (team_comms.*,
// game.*, vision.*, noise or noise.*, physics.*) and behaviour overrides
// (setups.<name or index>.config.*, setups.<name or index>.robots.<index>.config.*).
// A value is set into the file's tree at its path (missing maps are
// created; SweepTree puts the tree back after each cell) before the
// experiment's own readers (the scenario's and the behaviour's) validate it:
// one parser for base and swept values. An error a swept value causes is
// said at the value's line in the sweep list.
//
// Cells are numbered like nested loops in file order: the first path varies
// slowest. At most kMaxSweepCells cells, kMaxSweepPaths paths and
// kMaxSweepNodes YAML nodes read over all checks (each value alone, then
// each cell, reads the whole file's tree: the work is (values + cells) x
// nodes), each refused at its line (16 paths of one value each took 1 s,
// 3,000 took 65 s: each cell copied the setup once per path).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sim/world/ConfigError.hpp"

namespace simswift::experiment {

struct Experiment;

constexpr int kMaxSweepCells = 1000;
// Paths in one sweep: a cell sets every path (copying what it changes).
constexpr int kMaxSweepPaths = 16;
// (values + cells; values alone with one axis) x the file's YAML nodes but
// the sweep list's: the nodes the checks read in all. The readers take about
// 1 us per node (a 2 x 2 sweep over 2,500 setups, 45,000 nodes: 8 checks in
// 0.42 s with the parse); the shipped experiments have 110-210 nodes, so
// 1,000 cells fit with room to spare.
constexpr long long kMaxSweepNodes = 1LL << 19;

struct SweepValue {
  std::string label;  // as written: a scalar's text, else flow YAML
  int line = 0;       // 1-based, in the experiment file
  // The base with only this value applied (validated; checkBehaviours
  // checks it alone so an error names this value).
  std::shared_ptr<const Experiment> alone;
};

struct SweepAxis {
  std::string path;  // "team_comms.loss"
  int line = 0;      // 1-based line of the path's key
  std::vector<SweepValue> values;
};

// The `sweep:` map of `top` (the experiment's root): its shape only (a map
// of paths to non-empty lists, paths not overlapping, distinct values, at
// most kMaxSweepCells cells). Paths are resolved by applySweepValue.
std::vector<SweepAxis> readSweep(const YamlReader& top);

// Cells: the product of the list lengths (1 without axes).
int sweepCells(const std::vector<SweepAxis>& axes);
// Value index per axis of `cell` (the first axis varies slowest).
std::vector<int> sweepChoice(const std::vector<SweepAxis>& axes, int cell);
// "team_comms.loss=0.1, vision.ball.max_distance_mm=1500"
std::string cellLabel(const std::vector<SweepAxis>& axes, int cell);

// Sets value `value` of `axis` (its node in root's own sweep: list) at the
// axis's path in `root`, the experiment file's tree. It replaces entries of
// `root` only (the settings block or the setups list it changes, copied
// first), never a node of the file's tree, so YAML aliases (robots: *three)
// do not carry the value into other setups and SweepTree can undo it. Throws ConfigError at
// the path's line if the path is not sweepable or leads through something
// the base does not have (no such setup or robot, a scalar where a map
// would be).
void applySweepValue(YAML::Node root, const SweepAxis& axis, int value, const std::string& file);

// The file's tree with values applied and taken back: each cell is checked
// on the nodes of the one parse (a fresh parse per cell cost cells x file,
// the sweep's own list included: 1,000 values took 85 s in a 1 MB file).
class SweepTree {
 public:
  explicit SweepTree(YAML::Node root);  // saves the entries values may replace
  void apply(const SweepAxis& axis, int value, const std::string& file);
  void restore();                       // the saved entries back in place

 private:
  YAML::Node root_;
  std::vector<std::pair<std::string, YAML::Node>> saved_;
};

// An error found while validating with swept values, said where the values
// are: one value ("file:line: sweep.<path>[i] = <value>: <what>") or a cell
// (at the sweep: key, naming the cell's values).
ConfigError blameValue(const std::string& file, const SweepAxis& axis, int value, const std::string& what);
ConfigError blameCell(const std::string& file, int sweep_line, const std::vector<SweepAxis>& axes, int cell,
                      const std::string& what);

}  // namespace simswift::experiment
