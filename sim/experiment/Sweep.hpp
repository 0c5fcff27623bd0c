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
// A value is set into a fresh parse of the file at its path (missing maps
// are created) before the experiment's own readers (the scenario's and the
// behaviour's) validate it: one parser for base and swept values. An error
// a swept value causes is said at the value's line in the sweep list.
//
// Cells are numbered like nested loops in file order: the first path varies
// slowest. At most kMaxSweepCells cells.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sim/world/ConfigError.hpp"

namespace simswift::experiment {

struct Experiment;

constexpr int kMaxSweepCells = 1000;

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
// axis's path in `root`, a fresh parse of the experiment file. The setup or
// settings block it changes is copied first, so YAML aliases (robots:
// *three) do not carry the value into other setups. Throws ConfigError at
// the path's line if the path is not sweepable or leads through something
// the base does not have (no such setup or robot, a scalar where a map
// would be).
void applySweepValue(YAML::Node root, const SweepAxis& axis, int value, const std::string& file);

// An error found while validating with swept values, said where the values
// are: one value ("file:line: sweep.<path>[i] = <value>: <what>") or a cell
// (at the sweep: key, naming the cell's values).
ConfigError blameValue(const std::string& file, const SweepAxis& axis, int value, const std::string& what);
ConfigError blameCell(const std::string& file, int sweep_line, const std::vector<SweepAxis>& axes, int cell,
                      const std::string& what);

}  // namespace simswift::experiment
