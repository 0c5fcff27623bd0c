// The test file: what it accepts, its errors at file:line: key, the run
// seeds and the start-pose fuzz.
#include <gtest/gtest.h>

#include <cmath>

#include "app/scenario_tests/TestFile.hpp"
#include "app/scenario_tests/TestRun.hpp"
#include "tests/support/ConfigErrors.hpp"

namespace {

using namespace simswift::scenario_tests;

const std::string kTestFilePath = std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/tests/t.yaml";

std::string file(const std::string& tests, const std::string& head = "name: t\nseed: 3\n") {
  return head + "tests:\n" + tests;
}

const std::string kOne =
    "  - name: walk\n"
    "    seeds: 5\n"
    "    short: {seeds: 2}\n"
    "    time_limit: 4\n"
    "    required: 0.3\n"
    "    scenario:\n"
    "      ball: {x: 1.0, y: 0.5}\n"
    "      robots:\n"
    "        - {team: 19, player: 2, x: -1.0, y: 0.0, theta: 0.0}\n"
    "    fuzz: {robots: {x: 0.2, y: [0.0, 0.3], theta: 0.1}, ball: {x: 0.1, y: 0.1}}\n"
    "    pass: {never: {fallen: any}}\n";

std::string testFileError(const std::string& text) {
  return simswift::testing::configError([&] { TestFile::parse(text, kTestFilePath); });
}

TEST(TestFile, ReadsATestAndItsDefaults) {
  const TestFile f = TestFile::parse(file(kOne + "  - name: second\n    scenario: {robots: [{team: 19, player: 3}]}\n"
                                                 "    pass: {eventually: {time: {at_least: 1}}}\n",
                                          "name: t\nseed: 3\ndefaults: {seeds: 7, required: 0.5, time_limit: 9}\n"),
                                     kTestFilePath);
  ASSERT_EQ(f.tests.size(), 2u);
  EXPECT_EQ(f.tests[0].seeds, 5);
  EXPECT_EQ(f.tests[0].short_seeds, 2);
  EXPECT_DOUBLE_EQ(f.tests[0].time_limit, 4);
  EXPECT_DOUBLE_EQ(f.tests[0].scenario.duration, 4);  // the time limit is the scenario's duration
  EXPECT_EQ(f.tests[1].seeds, 7);
  EXPECT_EQ(f.tests[1].short_seeds, 7);  // no short: the same
  EXPECT_DOUBLE_EQ(f.tests[1].required, 0.5);
  EXPECT_DOUBLE_EQ(f.tests[1].time_limit, 9);
  EXPECT_EQ(countRuns(f, false), 12);
  EXPECT_EQ(countRuns(f, true), 9);
  const RunSpec s = runSpec(f, true, 3, 0, false);  // the second test's second run
  EXPECT_EQ(s.test, 1);
  EXPECT_EQ(s.run, 1);
}

TEST(TestFile, ErrorsNameTheLineAndKey) {
  EXPECT_NE(testFileError(file(kOne + kOne)).find("t.yaml:15: tests[1].name: a second test named walk"), std::string::npos)
      << testFileError(file(kOne + kOne));
  std::string typo = kOne;
  typo.replace(typo.find("seeds: 5"), 8, "sedes: 5");
  const std::string e = testFileError(file(typo));
  EXPECT_NE(e.find("t.yaml:5"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean seeds"), std::string::npos) << e;
  std::string bad_robot = kOne;
  bad_robot.replace(bad_robot.find("player: 2"), 9, "player: 9");
  EXPECT_NE(testFileError(file(bad_robot)).find("tests[0].scenario.robots[0].player"), std::string::npos)
      << testFileError(file(bad_robot));
  EXPECT_NE(testFileError(file("  - name: x\n    pass: {never: {fallen: 0}}\n")).find("tests[0]"), std::string::npos);
  EXPECT_NE(testFileError("name: t\ntests: []\n").find("needs at least one test"), std::string::npos);
  std::string required = kOne;
  required.replace(required.find("required: 0.3"), 13, "required: 1.5");
  EXPECT_NE(testFileError(file(required)).find("t.yaml:8: tests[0].required"), std::string::npos) << testFileError(file(required));
}

TEST(TestFile, ARequiredRateItsSeedsCannotConfirmIsRefused) {
  // 2 short seeds: 2/2 passes give a lower bound of 0.342.
  std::string t = kOne;
  t.replace(t.find("required: 0.3"), 13, "required: 0.5");
  const std::string e = testFileError(file(t));
  EXPECT_NE(e.find("t.yaml:8: tests[0].required: with 2 seeds even 2/2 passes give a 95 % lower bound of 0.342"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("use at least 4 seeds in short:"), std::string::npos) << e;  // 4/4: 0.51
  t.replace(t.find("required: 0.5"), 13, "required: 1.0");
  EXPECT_NE(testFileError(file(t)).find("a rate of 1 can never be confirmed"), std::string::npos);
}

// The advice names the least seed count the check accepts (issue 45, item
// 7): n/n's 95 % Wilson lower end is n / (n + z^2), z = 1.959964, which
// reaches 0.95 at n = 19 z^2 = 72.99, so 73; 72 is refused.
TEST(TestFile, TheAdvisedSeedCountIsTheLeastTheCheckAccepts) {
  const auto withSeeds = [](int seeds) {
    std::string t = kOne;
    const std::string counts = "seeds: 5\n    short: {seeds: 2}";
    t.replace(t.find(counts), counts.size(), "seeds: " + std::to_string(seeds));
    t.replace(t.find("required: 0.3"), 13, "required: 0.95");
    return file(t);
  };
  const std::string e = testFileError(withSeeds(20));
  EXPECT_NE(e.find("t.yaml:7: tests[0].required: with 20 seeds even 20/20 passes"), std::string::npos) << e;
  EXPECT_NE(e.find("use at least 73 seeds or a lower rate"), std::string::npos) << e;
  EXPECT_EQ(testFileError(withSeeds(73)), "");
  EXPECT_NE(testFileError(withSeeds(72)).find("use at least 73 seeds"), std::string::npos) << testFileError(withSeeds(72));
  // A rate no allowed count confirms (0.99999 needs 384,142) says so.
  std::string t = kOne;
  t.replace(t.find("required: 0.3"), 13, "required: 0.99999");
  EXPECT_NE(testFileError(file(t)).find("no seed count up to 100000 can: use a lower rate"), std::string::npos)
      << testFileError(file(t));
}

TEST(TestFile, AFuzzListLongerThanTheRobots) {
  std::string t = kOne;
  const std::string fuzz = "fuzz: {robots: {x: 0.2, y: [0.0, 0.3], theta: 0.1}";
  t.replace(t.find(fuzz), fuzz.size(), "fuzz: {robots: [{x: 0.1}, {x: 0.1}]");
  const std::string e = testFileError(file(t));
  EXPECT_NE(e.find("tests[0].fuzz.robots: lists 2 robots; the scenario has 1"), std::string::npos) << e;
}

TEST(TestFile, SeedsDependOnTheTestsNameAndRunOnly) {
  EXPECT_EQ(runSeed(3, "walk", 4), runSeed(3, "walk", 4));
  EXPECT_NE(runSeed(3, "walk", 4), runSeed(3, "walk", 5));
  EXPECT_NE(runSeed(3, "walk", 4), runSeed(3, "kick", 4));
  EXPECT_NE(runSeed(3, "walk", 4), runSeed(4, "walk", 4));
  EXPECT_LT(runSeed(3, "walk", 4), 2147483647u);  // `simswift run --seed` takes it
  // Adding a test before it does not move its seeds.
  const TestFile one = TestFile::parse(file(kOne), kTestFilePath);
  std::string other = kOne;
  other.replace(other.find("name: walk"), 10, "name: othr");
  const TestFile two = TestFile::parse(file(other + kOne), kTestFilePath);
  EXPECT_EQ(runSpec(one, false, 2, 0, false).seed, runSpec(two, false, 7, 0, false).seed);
}

TEST(TestFile, FuzzStaysInItsRangesAndIsAFunctionOfTheSeed) {
  const TestFile f = TestFile::parse(file(kOne), kTestFilePath);
  const ScenarioTest& t = f.tests[0];
  double min_y = 1, max_y = -1;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const simswift::runner::Scenario a = runScenario(t, seed), b = runScenario(t, seed);
    EXPECT_EQ(a.robots[0].x, b.robots[0].x);
    EXPECT_EQ(a.seed, seed);
    EXPECT_LE(std::fabs(a.robots[0].x + 1.0), 0.2);
    EXPECT_LE(std::fabs(a.robots[0].theta), 0.1);
    min_y = std::min(min_y, a.robots[0].y);
    max_y = std::max(max_y, a.robots[0].y);
    EXPECT_LE(std::fabs(a.ball->first - 1.0), 0.1);
  }
  EXPECT_GE(min_y, 0.0);
  EXPECT_LE(max_y, 0.3);
  EXPECT_GT(max_y - min_y, 0.25);  // 200 draws cover the range
}

TEST(TestFile, AFuzzOffTheCarpetIsRefusedBeforeAnyRun) {
  std::string t = kOne;
  t.replace(t.find("x: -1.0, y: 0.0"), 15, "x: -1.0, y: 3.5");
  const TestFile f = TestFile::parse(file(t), kTestFilePath);
  const std::string e = simswift::testing::configError([&] { checkPlacements(f, false, 0, false); });
  EXPECT_NE(e.find("t.yaml:4: tests[0] (walk), run "), std::string::npos) << e;
  EXPECT_NE(e.find("off the carpet"), std::string::npos) << e;
}

TEST(TestFile, AScenarioFileByName) {
  const TestFile f = TestFile::parse(
      file("  - name: stand\n    scenario: ../stand_one.yaml\n    pass: {never: {fallen: any}}\n"), kTestFilePath);
  EXPECT_EQ(f.tests[0].scenario.robots.size(), 1u);
  const std::string e = testFileError(file("  - name: stand\n    scenario: ../nothing.yaml\n    pass: {never: {fallen: any}}\n"));
  EXPECT_NE(e.find("t.yaml:5: tests[0].scenario: no scenario file"), std::string::npos) << e;
}

TEST(TestFile, ABaselineComparesTheSameMeasurementWhateverTheProgram) {
  const TestFile f = TestFile::parse(file(kOne), kTestFilePath);
  // Another program (behaviour, program), other seed counts and rate: the same measurement.
  std::string other = kOne;
  other.replace(other.find("theta: 0.0}"), 11, "theta: 0.0, behaviour: striker, program: builtin}");
  other.replace(other.find("seeds: 5"), 8, "seeds: 9");
  other.replace(other.find("required: 0.3"), 13, "required: 0.2");
  EXPECT_EQ(testDefinitions(file(other), "b.yaml").at("walk"), f.tests[0].definition);
  // A longer time limit or another condition: another test under the same name.
  std::string longer = kOne;
  longer.replace(longer.find("time_limit: 4"), 13, "time_limit: 5");
  EXPECT_NE(testDefinitions(file(longer), "b.yaml").at("walk"), f.tests[0].definition);
  std::string cond = kOne;
  cond.replace(cond.find("fallen: any"), 11, "fallen: 0");
  EXPECT_NE(testDefinitions(file(cond), "b.yaml").at("walk"), f.tests[0].definition);
}

TEST(ResultsRow, RoundTrips) {
  RunResult r;
  r.index = 12;
  r.test = "striker";
  r.run = 3;
  r.seed = 2147483646;
  r.passed = false;
  r.decided_s = 60;
  r.failure_s = 12.345;
  r.falls = 2;
  r.failure = "never: {fallen: any}: broken at 12.35 s, \"quoted\"";
  const RunResult b = parseResultsRow(resultsRow(r).substr(0, resultsRow(r).size() - 1));
  EXPECT_EQ(b.index, 12);
  EXPECT_EQ(b.test, "striker");
  EXPECT_EQ(b.seed, 2147483646u);
  EXPECT_FALSE(b.passed);
  EXPECT_DOUBLE_EQ(b.failure_s, 12.345);
  EXPECT_EQ(b.falls, 2);
  EXPECT_EQ(b.failure, r.failure);
}

}  // namespace

// A test file's seed is read by the one seed reader: every 64-bit value
// exactly, anything else refused at seed: with the range.
TEST(TestFileSeed, TakesAll64BitsAndNothingElse) {
  EXPECT_EQ(TestFile::parse(file(kOne, "name: t\nseed: 18446744073709551615\n"), kTestFilePath).seed,
            18446744073709551615ull);
  for (const char* bad : {"1.5", "-1", "18446744073709551616"}) {
    const std::string err = testFileError(file(kOne, "name: t\nseed: " + std::string(bad) + "\n"));
    EXPECT_NE(err.find("t.yaml:2: seed: must be a whole number in [0, 18446744073709551615]"), std::string::npos)
        << bad << ": " << err;
  }
}
