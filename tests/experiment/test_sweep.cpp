// Sweeps (app/experiment/Sweep.hpp): every combination of swept values is a
// cell with all the experiment's trials; results are a pure function of the
// file across --jobs and shards + merge; a swept value changes what the
// trial runs; bad sweeps are refused naming file, line and key; without a
// sweep nothing changes. Tiny script-robot experiments (8 s per trial).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app/experiment/Batch.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Report.hpp"
#include "app/experiment/Trial.hpp"
#include "tests/experiment/ExperimentTestUtil.hpp"

using namespace simswift;
using namespace simswift::experiment;
using exptest::readAll;
using exptest::runInto;

namespace {

// tinyExperiment(1) has 15 lines: `sweep:` is line 16, its first path 17.
const std::string kTiny = exptest::tinyExperiment(1);

// p_near 0: the detector never reports a ball nearer than its falloff
// start (1.5 m), so the walker cannot find position 1; p_near 1: it can.
// Team-comms loss changes nothing for a script robot (a determinism check).
const std::string kTwoByTwo = kTiny +
                              "sweep:\n"
                              "  vision.ball.p_near: [0, 1]\n"
                              "  team_comms.loss: [0, 0.5]\n";

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string l;
  while (std::getline(in, l)) out.push_back(l);
  return out;
}

std::vector<std::string> fields(const std::string& l) {
  std::vector<std::string> out;
  std::istringstream in(l);
  std::string f;
  while (std::getline(in, f, ',')) out.push_back(f);
  if (!l.empty() && l.back() == ',') out.push_back("");
  return out;
}

void expectSame(const std::string& a, const std::string& b, const std::vector<std::string>& files) {
  for (const std::string& f : files) {
    std::string x = readAll(a + "/" + f), y = readAll(b + "/" + f);
    if (f == "report.md") {
      x = deterministicPart(x);
      y = deterministicPart(y);
    }
    EXPECT_FALSE(x.empty()) << a << "/" << f;
    EXPECT_TRUE(x == y) << f << " differs between " << a << " and " << b;
  }
}

std::string behaviourCheckedError(const std::string& text) {
  try {
    const Experiment e = Experiment::parse(text, "bad.yaml");
    checkBehaviours(e, behaviourHooks());
  } catch (const ConfigError& err) {
    return err.what();
  }
  return "";
}

void expectErrorStartingWith(const std::string& text, const std::string& where, const std::string& what) {
  const std::string msg = behaviourCheckedError(text);
  EXPECT_EQ(msg.rfind(where, 0), 0u) << "message: " << msg << "\nexpected to start with: " << where;
  EXPECT_NE(msg.find(what), std::string::npos) << "message: " << msg << "\nexpected: " << what;
}

bool haveGnuplot() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

}  // namespace

TEST(Sweep, FourCellsAreTheSameWithOneOrTwoJobsAndShardsMerged) {
  const Experiment e = Experiment::parse(kTwoByTwo, "tiny.yaml");
  ASSERT_EQ(e.numCells(), 4);
  EXPECT_EQ(e.trialsPerCell(), 2);
  EXPECT_EQ(e.numTrials(), 8);
  const std::string one = exptest::freshDir("one"), two = exptest::freshDir("two"), s1 = exptest::freshDir("s1"),
                    s2 = exptest::freshDir("s2"), merged = exptest::freshDir("merged");
  const BatchOutcome o = runInto(e, one, 1);
  EXPECT_TRUE(o.assembled) << o.message;
  EXPECT_EQ(o.ran, 8);
  ASSERT_TRUE(runInto(e, two, 2).assembled);
  EXPECT_FALSE(runInto(e, s1, 1, 1, 2).assembled);  // trials 0, 2, 4, 6: half of every cell's
  EXPECT_FALSE(runInto(e, s2, 1, 2, 2).assembled);
  ASSERT_TRUE(mergeRuns({s1, s2}, merged).assembled);
  const std::vector<std::string> files = {"results.csv", "tracks.csv", "cells.csv", "report.md",
                                          "figures/sweep_vision_ball_p_near.dat", "figures/sweep_team_comms_loss.dat"};
  expectSame(one, two, files);
  expectSame(one, merged, files);

  // results.csv: each trial's cell and values; cell-major, so trials 2c and
  // 2c + 1 are cell c's positions 1 and 2, with the same seeds in every cell.
  const std::vector<std::string> rows = lines(readAll(one + "/results.csv"));
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[0].rfind("trial,cell,vision.ball.p_near,team_comms.loss,setup,position,repeat,seed,found,", 0), 0u)
      << rows[0];
  const char* p_near[] = {"0", "0", "1", "1"};
  const char* loss[] = {"0", "0.5", "0", "0.5"};
  for (int t = 0; t < 8; ++t) {
    const std::vector<std::string> f = fields(rows[t + 1]);
    ASSERT_GE(f.size(), 14u) << rows[t + 1];
    const int c = t / 2;
    EXPECT_EQ(f[0], std::to_string(t));
    EXPECT_EQ(f[1], std::to_string(c));
    EXPECT_EQ(f[2], p_near[c]);
    EXPECT_EQ(f[3], loss[c]);
    EXPECT_EQ(f[5], t % 2 == 0 ? "1" : "2");                        // position
    EXPECT_EQ(f[7], fields(rows[1 + t % 2])[7]) << "seed of trial " << t;  // common random numbers
    // The observable effect: position 1 (1.2 m ahead) is found only where
    // the detector reports near balls; position 2 never.
    const bool found = f[8] == "1";
    EXPECT_EQ(found, t % 2 == 0 && c >= 2) << rows[t + 1];
    if (found) {
      EXPECT_GT(std::stod(f[9]), 3.0);
      EXPECT_LT(std::stod(f[9]), 7.0);
    }
  }
  EXPECT_NE(fields(rows[1])[7], fields(rows[2])[7]);

  // cells.csv and the report: one row per cell with its statistics.
  const std::vector<std::string> cells = lines(readAll(one + "/cells.csv"));
  ASSERT_EQ(cells.size(), 5u);
  EXPECT_EQ(cells[0].rfind("cell,vision.ball.p_near,team_comms.loss,setup,first_trial,last_trial,tests,found,", 0), 0u);
  for (int c = 0; c < 4; ++c) {
    const std::vector<std::string> f = fields(cells[c + 1]);
    ASSERT_EQ(f.size(), 15u) << cells[c + 1];
    EXPECT_EQ(f[3], "walker");
    EXPECT_EQ(std::stoi(f[4]), 2 * c);             // first and last trial
    EXPECT_EQ(std::stoi(f[5]), 2 * c + 1);
    EXPECT_EQ(f[6], "2");                          // tests
    EXPECT_EQ(f[7], c >= 2 ? "1" : "0");           // found
    EXPECT_NEAR(std::stod(f[8]), c >= 2 ? 0.5 : 0.0, 1e-9);
    // Wilson 95 % for 1/2: [0.0945, 0.9055]; for 0/2: [0, 0.6576].
    EXPECT_NEAR(std::stod(f[9]), c >= 2 ? 0.0945 : 0.0, 2e-4);
    EXPECT_NEAR(std::stod(f[10]), c >= 2 ? 0.9055 : 0.6576, 2e-4);
    if (c >= 2) {  // one find: the bootstrap interval is that time
      EXPECT_DOUBLE_EQ(std::stod(f[11]), std::stod(f[12]));
      EXPECT_DOUBLE_EQ(std::stod(f[11]), std::stod(f[13]));
    } else {
      EXPECT_EQ(f[11], "");
    }
    EXPECT_FALSE(f[14].empty());                   // the bootstrap's seed
  }
  const std::string report = readAll(one + "/report.md");
  EXPECT_NE(report.find("8 trials: 4 sweep cells x 1 setup(s)"), std::string::npos);
  EXPECT_NE(report.find("## Sweep"), std::string::npos);
  EXPECT_NE(report.find("| 3 | 1 | 0.5 | `walker` | 1/2 | 50 % [9, 91] % |"), std::string::npos) << report;
  EXPECT_NE(report.find("| 0 | 0 | 0 | `walker` | 0/2 | 0 % [0, 66] % | - |"), std::string::npos) << report;
  if (haveGnuplot()) {
    EXPECT_TRUE(exptest::fileExists(one + "/figures/sweep_vision_ball_p_near.png"));
    EXPECT_TRUE(exptest::fileExists(one + "/figures/sweep_team_comms_loss.png"));
  }
}

// A swept value reaches the trial: the same trial (position 1, same seed)
// is found or not by the detector's near probability alone.
TEST(Sweep, ASweptValueChangesWhatTheTrialRuns) {
  const Experiment e = Experiment::parse(kTiny + "sweep:\n  vision.ball.p_near: [0, 1]\n", "tiny.yaml");
  ASSERT_EQ(e.numCells(), 2);
  const TrialResult blind = runTrial(e, 0, behaviourHooks()), seeing = runTrial(e, 2, behaviourHooks());
  EXPECT_EQ(blind.seed, seeing.seed);
  EXPECT_EQ(blind.position, 1);
  EXPECT_EQ(seeing.position, 1);
  EXPECT_FALSE(blind.found);
  EXPECT_TRUE(seeing.found);
  EXPECT_GT(seeing.seconds, 3.0);
  EXPECT_LT(seeing.seconds, 7.0);
  // The blind robot walks on past the ball for the whole 7 s.
  EXPECT_GT(blind.robots[0].distance_m, seeing.robots[0].distance_m + 0.2);
}

// The scenario settings an experiment takes as its base (read by the
// scenario's readers) and their swept values reach every trial's scenario.
TEST(Sweep, BaseSettingsAndSweptSettingsReachTheTrialScenario) {
  const std::string text = kTiny +
                           "team_comms: {loss: 0.25, delay_ms: 40}\n"
                           "physics: {substeps: 3}\n"
                           "noise: {fsr: off}\n"
                           "game: {half_duration: 300, kickoff_team: 1}\n"
                           "sweep:\n"
                           "  team_comms.loss: [0, 1]\n"
                           "  physics.iterations: [10, 30]\n";
  const Experiment e = Experiment::parse(text, "tiny.yaml");
  ASSERT_EQ(e.numCells(), 4);
  for (int c = 0; c < 4; ++c) {
    const runner::Scenario sc = trialScenario(e, trialSpec(e, c * e.trialsPerCell() + 1));
    EXPECT_DOUBLE_EQ(sc.team_comms.loss, c < 2 ? 0.0 : 1.0);
    EXPECT_DOUBLE_EQ(sc.team_comms.delay_ms, 40);  // the base's, kept beside the swept key
    EXPECT_EQ(sc.world.quick_iterations, c % 2 ? 30 : 10);
    EXPECT_EQ(sc.world.substeps, 3);
    EXPECT_TRUE(sc.noise.on);
    EXPECT_FALSE(sc.noise.fsr);
    EXPECT_DOUBLE_EQ(sc.game.half_duration_s, 300);
    EXPECT_EQ(sc.game.kickoff_team, 1);
    // The trial's own start stays: penalised, then PLAYING.
    EXPECT_EQ(sc.game.initial_state, common::libagent::GameStateValue::Initial);
    ASSERT_EQ(sc.game.timeline.size(), 1u);
  }
  expectErrorStartingWith(kTiny + "game: {state: ready}\n", "bad.yaml:16: game.state", "set by each trial");
  expectErrorStartingWith(kTiny + "team_comms: {loss: 2}\n", "bad.yaml:16: team_comms.loss", "must be in [0, 1]");
}

// Behaviour overrides by setup name: validated by the behaviour's own
// reader; a robots list shared by a YAML alias changes in one setup only.
TEST(Sweep, BehaviourOverridesBySetupAndRobot) {
  const std::string text =
      "name: b\nseed: 1\ntime_limit: 10\ntrials_per_position: 1\n"    // 1-4
      "balls:\n  - {position: 1, x: 1.0, y: 0.0}\n"                    // 5-6
      "setups:\n"                                                      // 7
      "  - name: a\n    behaviour: findball2017\n"                     // 8-9
      "    robots: &r\n      - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}\n"  // 10-11
      "  - name: b\n    behaviour: findball2017\n    robots: *r\n"     // 12-14
      "sweep:\n"                                                       // 15
      "  setups.b.robots.0.config.search.spin_at_point: [on, off]\n";  // 16
  const Experiment e = Experiment::parse(text, "b.yaml");
  ASSERT_EQ(e.numCells(), 2);
  EXPECT_NO_THROW(checkBehaviours(e, behaviourHooks()));
  EXPECT_EQ(e.cell(1).setups[1].robots[0].config_yaml, "{search: {spin_at_point: off}}");
  EXPECT_EQ(e.cell(1).setups[0].robots[0].config_yaml, "");  // the alias's other user is untouched
  EXPECT_EQ(e.setups[1].robots[0].config_yaml, "");          // and so is the base
  // A bad override value is refused by the behaviour's reader, at its line.
  const std::string bad = text.substr(0, text.rfind("  setups.b")) +
                          "  setups.1.config.search.spin_at_point:\n    - on\n    - sometimes\n";
  expectErrorStartingWith(bad, "bad.yaml:18: sweep.setups.1.config.search.spin_at_point[1] = sometimes", "spin_at_point");
  expectErrorStartingWith(text.substr(0, text.rfind("  setups.b")) + "  setups.a.config.search.spin_fast: [on]\n",
              "bad.yaml:16: sweep.setups.a.config.search.spin_fast[0] = on", "unknown key 'spin_fast'");
}

// Bad sweeps: each error names the file, the line and the key.
TEST(Sweep, BadSweepsAreRefusedAtTheirLine) {
  expectErrorStartingWith(kTiny + "sweep:\n  speed.max: [1, 2]\n", "bad.yaml:17: sweep.speed.max", "unknown path");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.lossy: [0.1]\n", "bad.yaml:17: sweep.team_comms.lossy[0] = 0.1",
              "unknown key 'lossy' in team_comms");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.loss:\n    - 0\n    - 2\n", "bad.yaml:19: sweep.team_comms.loss[1] = 2",
              "team_comms.loss: must be in [0, 1]");
  expectErrorStartingWith(kTiny + "sweep:\n  vision.ball.max_distance_mm: [1500, far]\n",
              "bad.yaml:17: sweep.vision.ball.max_distance_mm[1] = far", "max_distance_mm");
  expectErrorStartingWith(kTiny + "sweep:\n  physics.solver: [quick, 3]\n", "bad.yaml:17: sweep.physics.solver[1] = 3",
              "expected one of");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.loss: []\n", "bad.yaml:17: sweep.team_comms.loss", "an empty list");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.loss: 0.1\n", "bad.yaml:17: sweep.team_comms.loss", "must be a list");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.loss: [0.1, 0.1]\n", "bad.yaml:17: sweep.team_comms.loss",
              "appears twice");
  expectErrorStartingWith(kTiny + "sweep: []\n", "bad.yaml:16: sweep", "must be a map");
  expectErrorStartingWith(kTiny + "sweep:\n  setups.nope.config.grid.rows: [2]\n", "bad.yaml:17: sweep.setups.nope.config.grid.rows",
              "no setup 'nope' (setups: walker");
  expectErrorStartingWith(kTiny + "sweep:\n  setups.walker.robots.1.config.x: [2]\n",
              "bad.yaml:17: sweep.setups.walker.robots.1.config.x", "no robot '1'");
  expectErrorStartingWith(kTiny + "sweep:\n  setups.walker.x: [2]\n", "bad.yaml:17: sweep.setups.walker.x", "behaviour overrides");
  expectErrorStartingWith(kTiny + "noise: on\nsweep:\n  noise.gyro: [on, off]\n", "bad.yaml:18: sweep.noise.gyro",
              "'noise' is 'on' in the experiment, not a map");
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms..loss: [0]\n", "bad.yaml:17: sweep.team_comms..loss", "dotted path");
  expectErrorStartingWith(kTiny + "sweep:\n  vision.ball: [{}]\n  vision.ball.p_near: [1]\n", "bad.yaml:18: sweep.vision.ball.p_near",
              "overlaps sweep path vision.ball");
  expectErrorStartingWith(kTiny + "sweep:\n  found.sees: [on]\n", "bad.yaml:17: sweep.found.sees", "unknown path");
  // 2 x 10000 trials per cell x 60 cells: more than 10^6 trials.
  std::string sixty = "[0";
  for (int i = 1; i < 60; ++i) sixty += ", " + std::to_string(i);
  expectErrorStartingWith(exptest::tinyExperiment(10000) + "sweep:\n  team_comms.delay_ms: " + sixty + "]\n", "bad.yaml:16: sweep",
              "60 cells x 20000 trials = 1200000 trials is more than 1000000");
  // 11 x 11 x 11 = 1331 cells.
  const std::string eleven = "[0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]";
  expectErrorStartingWith(kTiny + "sweep:\n  team_comms.loss: " + eleven + "\n  vision.ball.p_near: " + eleven +
                  "\n  vision.ball.p_at_max: " + eleven + "\n",
              "bad.yaml:16: sweep", "more than 1000 cells (11 x 11 x 11");
}

// Two values each fine alone that clash together are refused naming the cell.
TEST(Sweep, ACellWhoseValuesClashIsNamed) {
  const std::string text = kTiny +
                           "vision: {ball: {max_distance_mm: 5000}}\n"
                           "sweep:\n"
                           "  vision.ball.min_distance_mm: [0, 3000]\n"
                           "  vision.ball.max_distance_mm: [2500, 5000]\n";
  const std::string msg = behaviourCheckedError(text);
  EXPECT_EQ(msg.rfind("bad.yaml:17: sweep: cell 2 (vision.ball.min_distance_mm=3000, vision.ball.max_distance_mm=2500): ", 0),
            0u)
      << msg;
  EXPECT_NE(msg.find("must be greater than min_distance_mm"), std::string::npos) << msg;
}

// The command line: exit code 2, the message at the value's line, no folder.
TEST(Sweep, CommandExitsWithTwoOnABadSweep) {
  const std::string dir = exptest::freshDir("cli");
  exptest::writeAll(dir + "/bad.yaml", kTiny + "sweep:\n  team_comms.loss:\n    - 0\n    - -1\n");
  const std::string cmd = exptest::simswiftBinary() + " experiment '" + dir + "/bad.yaml' --out '" + dir +
                          "/out' > '" + dir + "/stderr.txt' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = readAll(dir + "/stderr.txt");
  EXPECT_NE(err.find("bad.yaml:19: sweep.team_comms.loss[1] = -1: team_comms.loss: must be in [0, 1]"),
            std::string::npos)
      << err;
  EXPECT_FALSE(exptest::fileExists(dir + "/out"));
  // --check counts the cells.
  exptest::writeAll(dir + "/good.yaml", kTwoByTwo);
  const std::string check = exptest::simswiftBinary() + " experiment '" + dir + "/good.yaml' --check > '" + dir +
                            "/check.txt' 2>&1";
  EXPECT_EQ(std::system(check.c_str()), 0);
  EXPECT_NE(readAll(dir + "/check.txt").find("ok: 8 trials (4 cells x 1 setups x 2 positions x 1)"), std::string::npos)
      << readAll(dir + "/check.txt");
}

// Without a sweep: the results as before sweeps existed (header, seeds, no
// cells.csv); a one-value sweep of the base's own value runs the same
// trials, its rows only gaining the cell columns.
TEST(Sweep, WithoutASweepNothingChanges) {
  const Experiment plain = Experiment::parse(kTiny, "tiny.yaml");
  EXPECT_FALSE(plain.swept());
  // Seeds of seed 11's trials 0 and 1, as before sweeps (a pure function of
  // (seed, trial index)).
  EXPECT_EQ(trialSpec(plain, 0).seed, 1757773743u);
  EXPECT_EQ(trialSpec(plain, 1).seed, 248186634u);
  const Experiment same = Experiment::parse(kTiny + "sweep:\n  noise: [on]\n", "tiny.yaml");
  ASSERT_EQ(same.numCells(), 1);
  const std::string a = exptest::freshDir("plain"), b = exptest::freshDir("same");
  ASSERT_TRUE(runInto(plain, a, 2).assembled);
  ASSERT_TRUE(runInto(same, b, 2).assembled);
  const std::vector<std::string> pa = lines(readAll(a + "/results.csv")), pb = lines(readAll(b + "/results.csv"));
  ASSERT_EQ(pa.size(), 3u);
  ASSERT_EQ(pb.size(), 3u);
  EXPECT_EQ(pa[0],
            "trial,setup,position,repeat,seed,found,seconds,finder,resets,failed,robot1_player,robot1_distance_m,"
            "robot1_falls,robot1_contact_falls,robot1_sideline_moves");
  EXPECT_EQ(pb[0], "trial,cell,noise," + pa[0].substr(6));
  for (int i = 1; i <= 2; ++i) {
    const std::string t = std::to_string(i - 1);
    EXPECT_EQ(pb[i], t + ",0,on," + pa[i].substr(t.size() + 1));
  }
  EXPECT_EQ(readAll(a + "/tracks.csv"), readAll(b + "/tracks.csv"));
  EXPECT_FALSE(exptest::fileExists(a + "/cells.csv"));
  EXPECT_TRUE(exptest::fileExists(b + "/cells.csv"));
  const std::string report = deterministicPart(readAll(a + "/report.md"));
  EXPECT_EQ(report.find("Sweep"), std::string::npos);
  EXPECT_NE(report.find("2 trials: 1 setup(s) x 2 ball position(s) x 1 trial(s)."), std::string::npos) << report;
}
