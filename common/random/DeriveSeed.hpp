// The one recipe for deriving a seed from another (issue 32): every seeded
// stream in simswift (sensor noise, vision, robot programs, their filters,
// the team network, trial seeds, bootstrap intervals, test runs, the
// kinematic harness's start poses) takes its seed from its parent through
// deriveSeed, with a tag that says which child it is. Chains of derivations give independent-looking streams for
// (parent, tag, tag, ...) without any two recipes to keep apart.
#pragma once

#include <cstdint>

#include "common/random/SplitMix64.hpp"

namespace common::random {

// splitmix64 is a bijection, so for one parent distinct tags give distinct
// children; chaining (deriveSeed(deriveSeed(p, a), b)) rather than XORing
// the tags keeps (a, b) and (b, a) apart.
constexpr uint64_t deriveSeed(uint64_t parent, uint64_t tag) { return splitmix64(parent ^ tag); }

// The tags of the first derivation from a scenario's, an experiment's or a
// test file's seed. Tags need differ only among children of the same parent;
// a few are 0 because their recipe predates this one and their values are
// published or pinned (noted at each).
namespace seed_tag {

// From the scenario seed. deriveSeed(deriveSeed(deriveSeed(seed, kSensorNoise),
// robot index), stream id << 32): a robot's sensor and vision noise streams
// (sim/sensors/Noise.cpp streamSeed). 0: the recipe that was splitmix64(seed)
// first, kept so the sensor noise (and the pinned hashes) do not move.
constexpr uint64_t kSensorNoise = 0;
// From the scenario seed. deriveSeed(deriveSeed(seed, kRobotProgram), robot
// index): robot `index`'s program seed, handed to builtin and launched
// programs alike (sim/runner/Scenario.cpp programSeed). ASCII "program".
constexpr uint64_t kRobotProgram = 0x70726f6772616dULL;
// From the scenario seed: the in-process team network's drops
// (sim/network/TeamNetwork.cpp). ASCII "teamnet".
constexpr uint64_t kTeamNetwork = 0x7465616d6e6574ULL;
// From the scenario seed of a `simswift test` run: the fuzz of its robots' and
// ball's placements (app/scenario_tests/TestFile.cpp runScenario). ASCII "fuzz" << 32.
constexpr uint64_t kPlacementFuzz = 0x66757a7a00000000ULL;

// From a robot program's seed. deriveSeed(deriveSeed(seed, kLocalisation),
// the filter config's own seed): the localisation particle filter's random
// source (agent/program/ModuleOrder.cpp). ASCII "localise".
constexpr uint64_t kLocalisation = 0x6c6f63616c697365ULL;

// From an experiment's seed. deriveSeed(deriveSeed(seed, kTrial), trial
// index within its cell) % (2^31 - 1): a trial's scenario seed
// (app/experiment/Experiment.cpp trialSpec). 0: the recipe that was
// splitmix64(seed) first, kept so published trial seeds do not move (the
// seeds only: what a trial does with its seed moved with kRobotProgram).
constexpr uint64_t kTrial = 0;
// From an experiment's seed. deriveSeed(deriveSeed(deriveSeed(seed,
// kReportBootstrap), setup), position): the report's bootstrap interval of
// one (setup, position) (app/experiment/ReportStatistics.cpp). ASCII "report".
constexpr uint64_t kReportBootstrap = 0x7265706f7274ULL;
// From an experiment's seed. deriveSeed(deriveSeed(deriveSeed(seed,
// kSweepBootstrap), cell), setup): a sweep row's bootstrap interval
// (app/experiment/SweepReport.cpp). ASCII "sweep".
constexpr uint64_t kSweepBootstrap = 0x7377656570ULL;

// From a start-pose seed of the kinematic find-ball harness (1..5 in
// tools/findball_times.cpp, the closed-loop logic tests' seeds).
// deriveSeed(deriveSeed(seed, kTable51Start), player): robot `player`'s
// start-pose jitter (harness/Table51Setup.hpp jitter). A parent of its own:
// no other child to keep apart from. ASCII "table51".
constexpr uint64_t kTable51Start = 0x7461626c653531ULL;

// From a test file's seed: deriveSeed(deriveSeed(seed, FNV-1a of the test's
// name), run index) % (2^31 - 1), a run's scenario seed
// (app/scenario_tests/TestFile.cpp runSeed); the name is the tag.

// Children of one parent need distinct tags: checked when compiling.
static_assert(kSensorNoise != kRobotProgram && kSensorNoise != kTeamNetwork && kSensorNoise != kPlacementFuzz &&
                  kRobotProgram != kTeamNetwork && kRobotProgram != kPlacementFuzz && kTeamNetwork != kPlacementFuzz,
              "the scenario seed's children need distinct tags");
static_assert(kTrial != kReportBootstrap && kTrial != kSweepBootstrap && kReportBootstrap != kSweepBootstrap,
              "the experiment seed's children need distinct tags");

}  // namespace seed_tag

}  // namespace common::random
