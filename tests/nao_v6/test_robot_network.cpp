// A launched program's own network (sim/programs/RobotNetwork.hpp,
// sim/network/RobotLan.hpp), held against the facts-only network client
// (tests/net_client: GameController on 3838 bound to 0.0.0.0 with
// SO_REUSEADDR, team messages broadcast on 10000 + team): two V6 robots of
// team 47 and an opponent of team 46 that sends to team 47's port.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sim/programs/MountNamespace.hpp"
#include "sim/programs/RobotNetwork.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/Attach.hpp"

using simswift::runner::Runner;
using simswift::runner::Scenario;
using simswift::testing::exitCodeOf;
using simswift::testing::startAttach;

namespace {

const std::string kNetClient = std::string(SIMSWIFT_BINARY_DIR) + "/net-client";

std::vector<std::vector<std::string>> lines(const std::string& path) {
  std::vector<std::vector<std::string>> out;
  std::ifstream in(path);
  for (std::string l; std::getline(in, l);) {
    std::istringstream s(l);
    std::vector<std::string> w;
    for (std::string x; s >> x;) w.push_back(x);
    if (!w.empty()) out.push_back(w);
  }
  return out;
}

std::string readFile(const std::string& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct NetRun {
  uint64_t hash = 0;
  int64_t gc_sent = 0;
  std::string logs;
  std::map<std::string, std::string> seen;  // tag -> its program's output
  std::vector<int> attach_exit;              // each `simswift attach`'s exit status
};

// How t47p2's program is started: launched by the run, or by hand with
// `simswift attach` (directly or under gdb) on an external robot.
enum class Start { Launched, Attach, AttachUnderGdb };

// Team `us` (47) with two robots and an opponent `us` - 1 that sends to
// `us`'s port; each test its own teams (ctest runs tests side by side, and a
// robot's socket is named by its team and player).
NetRun runTeam(const std::string& name, double delay_ms, Start start = Start::Launched, int us = 47) {
  NetRun out;
  out.logs = "/tmp/simswift-test-net-" + std::to_string(getpid()) + "-" + name;
  std::filesystem::remove_all(out.logs);
  const std::string team = std::to_string(us), them = std::to_string(us - 1);
  const std::string p1 = "t" + team + "p1", p2 = "t" + team + "p2", opponent = "t" + them + "p1";
  std::ostringstream y;
  y << "duration: 2.4\nseed: 5\nprogram_logs: " << out.logs << "\n"
    << "game: {udp: on, version: 18, return_port: 0}\n"
    << "team_comms: {loss: 0, delay_ms: " << delay_ms << "}\n"
    << "robots:\n";
  const std::string client = "program: {command: [\"" + kNetClient + "\", \"{team}\", \"{player}\"";
  y << "  - {team: " << team << ", player: 1, x: -1, y: 1, lola: {}, " << client << "]}}\n";
  if (start == Start::Launched)
    y << "  - {team: " << team << ", player: 2, x: -1, y: -1, lola: {}, " << client << "]}}\n";
  else
    y << "  - {team: " << team << ", player: 2, x: -1, y: -1, lola: {}, program: external}\n";
  // The opponent sends to the team's port.
  y << "  - {team: " << them << ", player: 1, x: 1, y: 0, lola: {}, " << client << ", \"" << team << "\"]}}\n";
  Runner r(Scenario::parse(y.str(), out.logs + ".yaml"));
  simswift::runner::RunOptions o;
  o.progress = false;
  if (start == Start::Launched) {
    out.hash = r.run(o).hash;
  } else {
    r.start();  // the robot's view and clock page exist from here
    if (start == Start::Attach) {
      // First a shell in the view, what a program checks of its robot (it
      // is the first process there after the view's init: pid 2).
      const pid_t sh = startAttach(us, 2, {"/bin/sh", "-c",
                                        "echo pid $$; cat /sys/class/hwmon/hwmon1/temp2_input; "
                                        "test -S /tmp/robocup && echo robocup; test -d /home/nao && echo home; "
                                        "grep -o wlan0 /proc/net/dev; touch /tmp/mark"},
                                   out.logs + "/" + p2 + ".sh.log");
      out.attach_exit.push_back(exitCodeOf(sh));
    }
    std::vector<std::string> command = {kNetClient, team, "2"};
    if (start == Start::AttachUnderGdb)
      // SIGSYS: the shim's trap of raw clock syscalls (docs/shim.md; an
      // ASan runtime makes them), passed on as the docs tell gdb users.
      command.insert(command.begin(), {"/usr/bin/gdb", "-batch", "-nx", "-ex", "handle SIGSYS nostop noprint pass",
                                       "-ex", "run", "--args"});
    const pid_t program = startAttach(us, 2, command, out.logs + "/" + p2 + ".log");
    out.hash = r.run(o).hash;
    out.attach_exit.push_back(exitCodeOf(program));
  }
  out.gc_sent = r.gameControllerUdp()->sent();
  for (const std::string& tag : {p1, p2, opponent}) out.seen[tag] = readFile(out.logs + "/" + tag + ".log");
  return out;
}

// For robot `tag`: cycle received - cycle sent of every message from
// `from_address`, and the cycles sent that never arrived.
struct Heard {
  std::vector<int> delays;
  int heard = 0;
};
Heard heard(const NetRun& run, const std::string& receiver, const std::string& sender, const std::string& address,
            int last_cycle) {
  Heard h;
  std::map<int, int> sent;  // cycle -> 1
  for (const auto& w : lines(run.logs + "/" + sender + ".log"))
    if (w[0] == "sent") sent[std::stoi(w[1])] = 1;
  std::map<int, int> got;  // sent cycle -> received cycle
  for (const auto& w : lines(run.logs + "/" + receiver + ".log"))
    if (w[0] == "team" && w[2] == address) got[std::stoi(w[4].substr(1))] = std::stoi(w[1]);
  for (const auto& [c, one] : sent) {
    auto it = got.find(c);
    if (it == got.end()) {
      // Only the last messages may still be in flight at the end.
      EXPECT_GT(c, last_cycle - 10) << receiver << " never heard " << sender << "'s message of cycle " << c;
      continue;
    }
    ++h.heard;
    h.delays.push_back(it->second - c);
  }
  return h;
}

}  // namespace

TEST(RobotNetwork, TeammatesHearEveryGameControllerPacketAndEachOtherWithTheScenariosDelay) {
  if (!simswift::programs::mountNamespaceSupport().available || !simswift::programs::robotNetworkSupport().available) {
    GTEST_SKIP() << "this machine gives a program no network of its own: "
                 << simswift::programs::robotNetworkSupport().why << simswift::programs::mountNamespaceSupport().why;
  }
  const NetRun a = runTeam("a", 0);
  // Every robot: its address on wlan0, every GameController packet (none shared), from the GameController's address.
  for (const auto& [tag, address] : std::map<std::string, std::string>{{"t47p1", "10.0.47.1"},
                                                                       {"t47p2", "10.0.47.2"},
                                                                       {"t46p1", "10.0.46.1"}}) {
    const auto ls = lines(a.logs + "/" + tag + ".log");
    ASSERT_FALSE(ls.empty()) << tag;
    EXPECT_EQ(ls[0], (std::vector<std::string>{"addr", address, "10.0.255.255"})) << a.seen.at(tag);
    int gc = 0;
    for (const auto& w : ls) {
      EXPECT_NE(w[0], "fail") << tag << ": " << a.seen.at(tag);
      if (w[0] == "gc") {
        ++gc;
        EXPECT_EQ(w[3], "10.0.255.254");
        EXPECT_GT(std::stoi(w[2]), 4);
      }
    }
    // Every robot, the opponent launched last too, gets every packet (the
    // one of t = 0 is written after the first tick's answers, when every
    // program has bound its port; before, the opponent missed it).
    EXPECT_EQ(gc, a.gc_sent) << tag << " missed GameController packets: " << a.seen.at(tag);
  }
  EXPECT_EQ(a.gc_sent, 5);  // t = 0, 0.5, 1.0, 1.5, 2.0 s
  const int last = 2400 / 12 - 1;
  // Loss 0: each teammate hears every message of the other (but the last
  // ones, in flight at the end), all with one delay in ticks.
  const Heard h12 = heard(a, "t47p2", "t47p1", "10.0.47.1", last), h21 = heard(a, "t47p1", "t47p2", "10.0.47.2", last);
  EXPECT_GE(h12.heard, 18);
  EXPECT_GE(h21.heard, 18);
  ASSERT_FALSE(h12.delays.empty());
  const int base = h12.delays[0];
  for (int d : h12.delays) EXPECT_EQ(d, base);
  for (int d : h21.delays) EXPECT_EQ(d, base);
  // The opponent's messages (sent to team 47's port) never arrive.
  for (const char* tag : {"t47p1", "t47p2"})
    for (const auto& w : lines(a.logs + "/" + tag + ".log"))
      if (w[0] == "team") {
        EXPECT_NE(w[2], "10.0.46.1") << tag << " heard the opponent";
      }
  // Run again: the same hash and the same of everything each program saw.
  const NetRun b = runTeam("b", 0);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.seen, b.seen);
  // 36 ms of delay is 3 more ticks of 12 ms.
  const NetRun c = runTeam("c", 36);
  const Heard d12 = heard(c, "t47p2", "t47p1", "10.0.47.1", last);
  ASSERT_FALSE(d12.delays.empty());
  for (int d : d12.delays) EXPECT_EQ(d, base + 3);
  for (const NetRun* r : {&a, &b, &c}) std::filesystem::remove_all(r->logs);
}

// The program of an external robot started by hand with `simswift attach`
// (issue 44's view for attach, and item 5: under gdb too) meets what the
// launched one meets: its address, every GameController packet, its
// teammate's messages and only those, the same as the launched run to the
// line (the same hash); in its robot's PID namespace, with its files,
// /tmp/robocup and /home/nao, and a /tmp that is the run's folder of the view.
TEST(RobotNetwork, AProgramStartedWithAttachMeetsWhatTheLaunchedOneMeets) {
  if (!simswift::programs::mountNamespaceSupport().available || !simswift::programs::robotNetworkSupport().available) {
    GTEST_SKIP() << "this machine gives a program no network of its own: "
                 << simswift::programs::robotNetworkSupport().why << simswift::programs::mountNamespaceSupport().why;
  }
  // The program's own lines (gdb adds its own around them).
  const auto said = [](const NetRun& r, const std::string& tag) {
    std::string out;
    for (const auto& w : lines(r.logs + "/" + tag + ".log")) {
      if (w[0] != "addr" && w[0] != "gc" && w[0] != "team" && w[0] != "sent" && w[0] != "fail") continue;
      for (const std::string& x : w) out += x + " ";
      out += "\n";
    }
    return out;
  };
  // Teams 37 and 36: not the other test's, which ctest may run beside it.
  const NetRun launched = runTeam("launched", 0, Start::Launched, 37);
  const NetRun attached = runTeam("attached", 0, Start::Attach, 37);
  EXPECT_EQ(attached.attach_exit, (std::vector<int>{0, 0})) << readFile(attached.logs + "/t37p2.sh.log")
                                                            << readFile(attached.logs + "/t37p2.log");
  EXPECT_EQ(readFile(attached.logs + "/t37p2.sh.log"), "pid 2\n50000\nrobocup\nhome\nwlan0\n");
  EXPECT_TRUE(std::filesystem::exists(attached.logs + "/t37p2.view/tmp/mark"));
  for (const char* tag : {"t37p1", "t37p2", "t36p1"}) {
    EXPECT_FALSE(said(launched, tag).empty()) << tag;
    EXPECT_EQ(said(attached, tag), said(launched, tag)) << tag << ": " << attached.seen.at(tag);
  }
  EXPECT_EQ(attached.hash, launched.hash);
  if (::access("/usr/bin/gdb", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/gdb";
  const NetRun gdb = runTeam("gdb", 0, Start::AttachUnderGdb, 37);
  EXPECT_EQ(gdb.attach_exit, std::vector<int>{0}) << gdb.seen.at("t37p2");
  EXPECT_EQ(said(gdb, "t37p2"), said(launched, "t37p2")) << gdb.seen.at("t37p2");
  EXPECT_EQ(gdb.hash, launched.hash);
  for (const NetRun* r : {&launched, &attached, &gdb}) std::filesystem::remove_all(r->logs);
}
