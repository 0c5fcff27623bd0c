// The command lines of simswift and simswift-agent (app/cli, CLI11): --help
// is generated from the declarations the parser reads, so every option a
// help lists is one the parser takes; an unknown option or a bad number
// exits with code 2 and a message naming the option; a seed is read by the
// seed reader's decimal rule (CLI11 alone reads 010 as octal 8).
#include <gtest/gtest.h>

#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "common/lock/PidLock.hpp"
#include "sim/programs/ClockPage.hpp"
#include "tests/support/Shell.hpp"
#include "tests/support/Sockets.hpp"

namespace {

using simswift::testing::shell;
using simswift::testing::ShellResult;

const std::string kSimswift = std::string(SIMSWIFT_BINARY_DIR) + "/simswift";
const std::string kAgent = std::string(SIMSWIFT_BINARY_DIR) + "/simswift-agent";
const std::string kScenario = std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/stand_one.yaml";

// Every --option the text names.
std::set<std::string> optionsIn(const std::string& text) {
  std::set<std::string> found;
  const std::regex option("--[a-z][a-z-]*");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
    found.insert(it->str());
  return found;
}

struct Command {
  std::string program;                // with its subcommands
  std::vector<std::string> options;   // what the command line takes (before CLI11 too)
};

const std::vector<Command> kCommands = {
    {kSimswift + " run",
     {"--realtime", "--check", "--inline", "--duration", "--seed", "--no-noise", "--watchdog", "--model", "--field",
      "--attach-timeout", "--print-hash-every", "--quiet", "--dump-frames", "--every", "--overview", "--resolution",
      "--findball-view", "--findball-view-rate", "--record", "--record-rate"}},
    {kSimswift + " experiment", {"--out", "--jobs", "--shard", "--progress", "--trial", "--record", "--check"}},
    {kSimswift + " experiment merge", {"--out"}},
    {kSimswift + " test",
     {"--short", "--only", "--out", "--jobs", "--shard", "--seed", "--baseline", "--alpha", "--junit", "--progress",
      "--test", "--trial", "--overview", "--record", "--check", "--merge"}},
    {kSimswift + " clean", {"--team", "--player"}},
    {kSimswift + " attach", {"--team", "--player", "--socket", "--clock", "--wait"}},
    {kSimswift + " view", {"--port", "--no-browser", "--at"}},
    {kAgent,
     {"--team", "--player", "--config", "--behaviour", "--seed", "--start", "--bare", "--posture", "--move", "--at",
      "--print", "--attach-timeout", "--lola"}},
};

void expectRefused(const std::string& args, const std::string& message) {
  const ShellResult r = shell(args + " </dev/null");
  EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << args << "\nwanted: " << message << "\n" << r.output;
}

}  // namespace

// Each subcommand's --help lists the options the command line has always
// taken; and every option a help lists is one its parser knows (given
// without its value or the files it needs, the parser says what is missing,
// never "not expected").
TEST(CommandLine, EachHelpListsTheOptionsItsParserTakes) {
  for (const Command& c : kCommands) {
    SCOPED_TRACE(c.program);
    const ShellResult help = shell(c.program + " --help 2>/dev/null");
    ASSERT_EQ(help.code, 0) << help.output;
    const std::set<std::string> listed = optionsIn(help.output);
    for (const std::string& o : c.options) EXPECT_EQ(listed.count(o), 1u) << o << " missing from\n" << help.output;
    for (const std::string& o : listed) {
      if (o == "--help") continue;
      const ShellResult r = shell(c.program + " " + o + " </dev/null");
      EXPECT_EQ(r.code, 2) << o << "\n" << r.output;  // a value or a file is missing
      EXPECT_EQ(r.output.find("not expected"), std::string::npos) << o << "\n" << r.output;
    }
  }
  // The top level names every subcommand.
  const ShellResult top = shell(kSimswift + " --help");
  EXPECT_EQ(top.code, 0) << top.output;
  for (const char* sub : {"run", "experiment", "test", "clean", "attach", "view"})
    EXPECT_NE(top.output.find(std::string("\n  ") + sub + " "), std::string::npos) << sub << "\n" << top.output;
  EXPECT_EQ(shell(kSimswift + " help").output, top.output);
}

TEST(CommandLine, AnUnknownOptionExitsTwoNamingIt) {
  expectRefused(kSimswift + " run " + kScenario + " --bogus", "--bogus");
  expectRefused(kSimswift + " experiment x.yaml --bogus", "--bogus");
  expectRefused(kSimswift + " experiment merge a --out b --bogus", "--bogus");
  expectRefused(kSimswift + " experiment merge a --out b --jobs 2", "--jobs");  // the run's, not merge's
  expectRefused(kSimswift + " test x.yaml --bogus", "--bogus");
  expectRefused(kSimswift + " clean --bogus", "--bogus");
  expectRefused(kSimswift + " attach --bogus -- true", "--bogus");
  expectRefused(kSimswift + " view x.mcap --bogus", "--bogus");
  expectRefused(kSimswift + " --bogus", "unknown option '--bogus'");
  expectRefused(kSimswift + " bogus", "unknown command 'bogus'");
  expectRefused(kAgent + " --bogus", "--bogus");
  // The subcommand the error is in, and where its help is.
  expectRefused(kSimswift + " test x.yaml --bogus", "simswift test: ");
  expectRefused(kSimswift + " test x.yaml --bogus", "simswift test --help");
}

TEST(CommandLine, ABadNumberExitsTwoNamingTheOption) {
  const std::string run = kSimswift + " run " + kScenario;
  expectRefused(run + " --duration abc", "--duration: bad value 'abc' (must be in [0.01, 1e+06])");
  expectRefused(run + " --duration 0", "--duration: bad value '0'");
  expectRefused(run + " --duration", "--duration");  // no value
  expectRefused(run + " --seed -1", "--seed: must be a whole number in [0, 18446744073709551615] (got '-1')");
  expectRefused(run + " --seed 0x10", "--seed: must be a whole number");
  expectRefused(run + " --watchdog soon", "--watchdog: bad value 'soon'");
  expectRefused(run + " --dump-frames /tmp/x --every 1.5", "--every: bad value '1.5' (must be a whole number");
  expectRefused(kSimswift + " clean --team 0x13 --player 1", "--team: bad value '0x13' (must be a whole number");
  expectRefused(kSimswift + " clean --team 1.9e1 --player 1", "--team: bad value '1.9e1' (must be a whole number");
  expectRefused(run + " --print-hash-every 0", "--print-hash-every: bad value '0'");
  expectRefused(run + " --resolution 320x240", "--resolution: must be 640x480 or 1280x960 (got '320x240')");
  expectRefused(kSimswift + " experiment x.yaml --jobs 0", "--jobs: must be a whole number in [1, 1000000] (got '0')");
  expectRefused(kSimswift + " experiment x.yaml --jobs +2", "--jobs: must be a whole number");
  expectRefused(kSimswift + " experiment x.yaml --shard 3/2", "--shard: needs K/N with 1 <= K <= N");
  expectRefused(kSimswift + " experiment x.yaml --trial -1", "--trial: must be a whole number");
  expectRefused(kSimswift + " test x.yaml --jobs 5000", "--jobs: must be a whole number in [1, 4096] (got '5000')");
  expectRefused(kSimswift + " test x.yaml --alpha 1", "--alpha: must be a level in (0, 1) (got '1')");
  expectRefused(kSimswift + " test x.yaml --seed 1e3", "--seed: must be a whole number in [0, 18446744073709551615]");
  expectRefused(kSimswift + " test x.yaml --test a --trial x", "--trial: must be a whole number");
  expectRefused(kSimswift + " clean --team 256 --player 1", "--team: bad value '256' (must be a whole number in [0, 255])");
  expectRefused(kSimswift + " attach --team 1 --player 9 -- true", "--player: bad value '9'");
  expectRefused(kAgent + " --start 1 x 3", "--start: not a number: 'x'");
  expectRefused(kAgent + " --move HeadYaw fast", "--move: not a number: 'fast'");
  expectRefused(kAgent + " --team 1 --player 1 --seed 99999999999999999999",
                "--seed: must be a whole number in [0, 18446744073709551615] (got '99999999999999999999')");
}

// Options that go together or exclude each other, named by the parser.
TEST(CommandLine, OptionsThatGoTogetherAreNamed) {
  expectRefused(kSimswift + " run " + kScenario + " --every 2", "--every requires --dump-frames");
  expectRefused(kSimswift + " run " + kScenario + " --findball-view-rate 2", "--findball-view-rate requires --findball-view");
  expectRefused(kSimswift + " test x.yaml --trial 1", "--trial requires --test");
  expectRefused(kSimswift + " test x.yaml --merge a b", "--merge requires --out");
  expectRefused(kSimswift + " clean --team 1", "--team requires --player");
  expectRefused(kSimswift + " attach --socket /tmp/s --team 1 --player 1 -- true", "--team excludes --socket");
  expectRefused(kSimswift + " attach --socket /tmp/s true", "unknown argument 'true' (the command goes after --)");
  expectRefused(kSimswift + " attach --socket /tmp/s --", "no command after --");
  expectRefused(kSimswift + " experiment x.yaml merge a --out b", "merge excludes FILE");
}

// A seed with a leading zero is decimal (the seed reader's rule): 010 runs
// as 10, not as octal 8 (what CLI11's own conversion would read).
TEST(CommandLine, ASeedIsDecimal) {
  auto hashOf = [](const std::string& seed) {
    const ShellResult r = shell(kSimswift + " run " + kScenario + " --duration 0.5 --quiet --seed " + seed);
    EXPECT_EQ(r.code, 0) << r.output;
    const size_t h = r.output.find("| hash ");
    return h == std::string::npos ? std::string("none") : r.output.substr(h + 7, 16);
  };
  const std::string ten = hashOf("10");
  EXPECT_EQ(hashOf("010"), ten);
  EXPECT_NE(hashOf("8"), ten);  // the seed changes the noise: the check can fail
}

// attach hands everything after the first `--` to the command untouched,
// options and further `--` included.
TEST(CommandLine, AttachPassesEverythingAfterTheDashesThrough) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("simswift_cmdline_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string socket_path = (dir / "robocup").string();
  const int fd = simswift::testing::bindUnix(socket_path);
  ASSERT_GE(fd, 0);
  // Served, as a run serves it: the run's lock beside the socket (attach
  // waits for a served socket, sim/lola/LolaServer.hpp).
  common::lock::PidLock served(socket_path + ".lock");
  ASSERT_TRUE(served.tryLock(0));
  // The robot's clock page, as a run makes it (the socket is not named by its robot: --clock).
  const std::string clock = "/simswift-clock-cmdline-" + std::to_string(getpid());
  simswift::programs::ClockPage page(clock, 12'000'000, 0);
  const ShellResult r = shell(kSimswift + " attach --socket " + socket_path + " --clock " + clock +
                              " -- /bin/sh -c 'printf \"%s|\" \"$@\"' sh --help -- --team 'a b' -x");
  ::close(fd);
  fs::remove_all(dir);
  if (r.output.find("mount namespace") != std::string::npos) GTEST_SKIP() << r.output;
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, "--help|--|--team|a b|-x|");
}

// A killed run leaves its robot's clock page behind, set up (its magic) and
// naming a pid that is gone: `simswift attach` waits for a live run and
// never starts the command on that page (a V5 robot: no socket to ask).
TEST(CommandLine, AttachTakesNoClockPageAKilledRunLeft) {
  const std::string tag = "t91p3";
  const pid_t run = ::fork();
  if (run == 0) {
    new simswift::programs::ClockPage(common::clock::pageName(tag), 10'000'000, 0);  // never unlinked
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(run, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const ShellResult r = shell(kSimswift + " attach --team 91 --player 3 --wait 0.3 -- /bin/echo started");
  ::shm_unlink(common::clock::pageName(tag).c_str());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_EQ(r.output.find("started"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no run served robot t91p3"), std::string::npos) << r.output;
}
