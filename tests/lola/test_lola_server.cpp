// The LoLA server endpoint on a real Unix socket: a cycle, a packet split
// across writes, garbage, a client that disconnects and reconnects, one that
// stops reading, and the facts-only client (tests/lola_client) as a process.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

#include "sim/lola/LolaServer.hpp"
#include "tests/support/Sockets.hpp"

using namespace simswift::lola;
using namespace std::chrono_literals;
using Status = Exchange::Status;

namespace {

std::string socketPath(const char* name) {
  return "/tmp/simswift-lola-test-" + std::to_string(::getpid()) + "-" + name;
}

using simswift::testing::connectUnix;

// Reads one whole packet; false at end of stream.
bool readPacket(int fd, PacketBytes& out) {
  return simswift::testing::readFully(fd, out.data(), out.size()) == out.size();
}

void writeAll(int fd, const std::string& bytes) { ASSERT_TRUE(simswift::testing::writeAll(fd, bytes)); }

ActuatorCommand joints(float position, float stiffness) {
  ActuatorCommand c;
  c.position.emplace();
  c.position->fill(position);
  c.stiffness.emplace();
  c.stiffness->fill(stiffness);
  return c;
}

SensorPacket packetWithKnee(float knee) {
  SensorPacket p;
  p.position[LKneePitch] = knee;
  return p;
}

}  // namespace

TEST(LolaServer, WaitsForAClientThenExchangesOneCycle) {
  LolaServer server(socketPath("cycle"));
  EXPECT_EQ(server.exchange(encodeSensorPacket({}), 20ms).status, Status::NoClient);

  std::thread client([&] {
    const int fd = connectUnix(server.path());
    ASSERT_GE(fd, 0);
    PacketBytes p;
    ASSERT_TRUE(readPacket(fd, p));
    const auto sensors = decodeSensorPacket(p.data(), p.size());
    ASSERT_TRUE(sensors);
    // Answer with the knee angle it read, as every joint's target.
    writeAll(fd, encodeActuatorMap(joints(sensors->position[LKneePitch], 1.f)));
    ::close(fd);
  });
  const Exchange e = server.exchange(encodeSensorPacket(packetWithKnee(1.25f)), 5000ms);
  client.join();
  ASSERT_EQ(e.status, Status::Answered) << toString(e.status) << " " << e.error;
  EXPECT_TRUE(e.new_client);
  EXPECT_FLOAT_EQ((*e.command.position)[RAnkleRoll], 1.25f);
}

TEST(LolaServer, AnAnswerSplitAcrossWritesIsOneAnswer) {
  LolaServer server(socketPath("split"));
  std::thread client([&] {
    const int fd = connectUnix(server.path());
    ASSERT_GE(fd, 0);
    for (int cycle = 0; cycle < 3; ++cycle) {
      PacketBytes p;
      ASSERT_TRUE(readPacket(fd, p));
      const std::string bytes = encodeActuatorMap(joints(0.1f * cycle, 0.5f));
      for (std::size_t at = 0; at < bytes.size(); at += 50) {
        writeAll(fd, bytes.substr(at, 50));
        std::this_thread::sleep_for(1ms);
      }
    }
    ::close(fd);
  });
  for (int cycle = 0; cycle < 3; ++cycle) {
    const Exchange e = server.exchange(encodeSensorPacket({}), 5000ms);
    ASSERT_EQ(e.status, Status::Answered) << toString(e.status) << " " << e.error;
    EXPECT_FLOAT_EQ((*e.command.position)[0], 0.1f * cycle);
  }
  client.join();
}

TEST(LolaServer, AClientThatDoesNotAnswerTimesOut) {
  LolaServer server(socketPath("timeout"));
  const int fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  const auto start = std::chrono::steady_clock::now();
  const Exchange e = server.exchange(encodeSensorPacket({}), 50ms);
  EXPECT_EQ(e.status, Status::Timeout);
  EXPECT_GE(std::chrono::steady_clock::now() - start, 50ms);
  EXPECT_TRUE(server.connected());  // still its client: it may answer late
  // Lock-step waits on for the same cycle: the late answer is this cycle's,
  // and the next cycle's packet gets the next answer (no lag of one).
  writeAll(fd, encodeActuatorMap(joints(0.3f, 1.f)));
  const Exchange late = server.awaitAnswer(1000ms);
  ASSERT_EQ(late.status, Status::Answered);
  EXPECT_FLOAT_EQ((*late.command.position)[5], 0.3f);
  PacketBytes first, second;
  ASSERT_TRUE(readPacket(fd, first));  // the timed-out cycle's packet, sent once
  writeAll(fd, encodeActuatorMap(joints(0.4f, 1.f)));
  const Exchange next = server.exchange(encodeSensorPacket({}), 1000ms);
  ASSERT_EQ(next.status, Status::Answered);
  EXPECT_FLOAT_EQ((*next.command.position)[5], 0.4f);
  ASSERT_TRUE(readPacket(fd, second));
  ::close(fd);
}

TEST(LolaServer, ALiveServersSocketIsRefusedNotTakenOver) {
  LolaServer first(socketPath("live"));
  try {
    LolaServer second(first.path());
    ADD_FAILURE() << "a second server took over " << first.path();
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("another server is listening there"), std::string::npos) << e.what();
  }
  const int fd = connectUnix(first.path());  // the first still serves
  EXPECT_GE(fd, 0);
  if (fd >= 0) ::close(fd);
}

// Asking whether a socket is live never touches its client (issue 45: a
// `simswift clean` during a V6 run, or a second run of the same robot,
// connected to find out; the live server took the probe as its newest
// client and dropped the program's). Each step is followed by a cycle that
// the first client must answer on its first connection.
TEST(LolaServer, CleanAndASecondServerLeaveTheLiveClientConnected) {
  const std::string name = "clean-" + std::to_string(::getpid());
  LolaServer server(socketPath(name.c_str()));
  const int fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  PacketBytes p;
  const auto cycle = [&](const char* after) {
    writeAll(fd, encodeActuatorMap(joints(0.3f, 1.f)));
    const Exchange e = server.exchange(encodeSensorPacket({}), 1000ms);
    EXPECT_EQ(e.status, Status::Answered) << after << ": " << toString(e.status);
    EXPECT_EQ(server.clientsAccepted(), 1) << after;
    EXPECT_TRUE(readPacket(fd, p)) << after;
  };
  cycle("the first cycle");
  // `simswift clean`: the live socket is left, not connected to.
  const std::string file = server.path().substr(std::string("/tmp/").size());
  EXPECT_TRUE(removeStaleSockets({"/tmp"}, file).empty());
  struct stat st{};
  EXPECT_EQ(::stat(server.path().c_str(), &st), 0);
  cycle("simswift clean");
  // A second server of the same robot: refused, naming the first's pid.
  try {
    LolaServer second(server.path());
    ADD_FAILURE() << "a second server took over " << server.path();
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("(pid " + std::to_string(::getpid()) + ")"), std::string::npos) << e.what();
  }
  cycle("a second server");
  ::close(fd);
}

// Newest wins only for a live newcomer: a connection that has already hung
// up (a probe of another tool, a client that gave up) is closed unseen.
TEST(LolaServer, AConnectionThatHasHungUpNeverReplacesTheClient) {
  LolaServer server(socketPath("hungup"));
  const int fd = connectUnix(server.path());
  ASSERT_TRUE(server.acceptPending());
  const int probe = connectUnix(server.path());
  ASSERT_GE(probe, 0);
  ::close(probe);
  writeAll(fd, encodeActuatorMap(joints(0.6f, 1.f)));
  const Exchange e = server.exchange(encodeSensorPacket({}), 1000ms);
  EXPECT_EQ(e.status, Status::Answered) << toString(e.status);
  EXPECT_FALSE(e.new_client);
  EXPECT_EQ(server.clientsAccepted(), 1);
  ::close(fd);
}

// A killed server leaves its socket and lock file; the lock went with it,
// so `simswift clean` removes both and the next server binds.
TEST(LolaServer, AKilledServersSocketIsCleanedAndTakenOver) {
  const std::string name = "killed-" + std::to_string(::getpid());
  const std::string path = socketPath(name.c_str());
  const pid_t child = ::fork();
  if (child == 0) {
    LolaServer s(path);
    ::_exit(::kill(::getpid(), SIGKILL));
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  struct stat st{};
  ASSERT_EQ(::lstat(path.c_str(), &st), 0) << "the killed server left its socket";
  const std::vector<std::string> removed = removeStaleSockets({"/tmp"}, path.substr(std::string("/tmp/").size()));
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_NE(::lstat(path.c_str(), &st), 0);
  EXPECT_NE(::lstat((path + ".lock").c_str(), &st), 0);
  LolaServer next(path);
}

// The shared socket folder is every user's, as /tmp is (issue 45: made with
// the umask by the first user's run, 0755, a second user's bind failed with
// EACCES). Root's run makes (or, made by an older simswift, sets) it
// 01777; then user nobody (65534) in a forked child binds a robot's socket
// there too. Team 97 is used by no other test.
TEST(LolaServer, TheSharedSocketFolderTakesSocketsOfEveryUser) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to run a child as another user";
  const std::string dir = kSharedSocketFolder;
  struct stat st{};
  if (::lstat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == 0)
    ::chmod(dir.c_str(), 0755);  // as an older simswift left it
  const mode_t old_umask = ::umask(022);
  LolaServer root_run(dir + "/t97p1");
  ::umask(old_umask);
  ASSERT_EQ(::lstat(dir.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, static_cast<mode_t>(01777));
  const pid_t child = ::fork();
  if (child == 0) {
    if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(4);
    try {
      { LolaServer other_user(dir + "/t97p2"); }  // bound, then removed
      ::_exit(0);
    } catch (const ServerError& e) {
      std::fprintf(stderr, "user 65534: %s\n", e.what());
      ::_exit(3);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "user 65534 could not bind in " << dir << " (4: setuid failed)";
}

TEST(LolaServer, GarbageClosesTheConnectionAndTheClientMayReconnect) {
  LolaServer server(socketPath("garbage"));
  int fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  writeAll(fd, std::string("\xc1\xc1\xc1", 3));
  const Exchange e = server.exchange(encodeSensorPacket({}), 1000ms);
  EXPECT_EQ(e.status, Status::ProtocolError);
  EXPECT_NE(e.error.find("not a msgpack map"), std::string::npos) << e.error;
  EXPECT_FALSE(server.connected());
  PacketBytes p;
  EXPECT_TRUE(readPacket(fd, p));   // the packet had been sent
  EXPECT_FALSE(readPacket(fd, p));  // then the server closed the connection
  ::close(fd);

  fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  writeAll(fd, encodeActuatorMap(joints(0.4f, 1.f)));
  const Exchange again = server.exchange(encodeSensorPacket({}), 1000ms);
  ASSERT_EQ(again.status, Status::Answered) << again.error;
  EXPECT_TRUE(again.new_client);
  EXPECT_EQ(server.clientsAccepted(), 2);
  ::close(fd);
}

TEST(LolaServer, DisconnectThenReconnect) {
  LolaServer server(socketPath("reconnect"));
  int fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  ASSERT_TRUE(server.acceptPending());  // accepted live (one that hung up before would never be the client)
  // A half-sent map, then the client goes: the half map is forgotten.
  const std::string bytes = encodeActuatorMap(joints(0.9f, 1.f));
  writeAll(fd, bytes.substr(0, 40));
  ::close(fd);
  const Exchange gone = server.exchange(encodeSensorPacket({}), 1000ms);
  EXPECT_EQ(gone.status, Status::Disconnected) << toString(gone.status);
  EXPECT_FALSE(server.connected());
  EXPECT_EQ(server.exchange(encodeSensorPacket({}), 20ms).status, Status::NoClient);

  fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  writeAll(fd, bytes.substr(40));  // the old map's rest is garbage on a new connection
  const Exchange bad = server.exchange(encodeSensorPacket({}), 1000ms);
  EXPECT_EQ(bad.status, Status::ProtocolError);
  ::close(fd);

  fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  writeAll(fd, bytes);
  const Exchange back = server.exchange(encodeSensorPacket({}), 1000ms);
  ASSERT_EQ(back.status, Status::Answered) << back.error;
  EXPECT_FLOAT_EQ((*back.command.position)[0], 0.9f);
  ::close(fd);
}

TEST(LolaServer, TheNewestConnectionWins) {
  LolaServer server(socketPath("newest"));
  const int old_fd = connectUnix(server.path());
  ASSERT_TRUE(server.acceptPending());
  const int new_fd = connectUnix(server.path());
  writeAll(new_fd, encodeActuatorMap(joints(0.6f, 1.f)));
  const Exchange e = server.exchange(encodeSensorPacket({}), 1000ms);
  ASSERT_EQ(e.status, Status::Answered);
  EXPECT_TRUE(e.new_client);
  PacketBytes p;
  EXPECT_FALSE(readPacket(old_fd, p));  // closed without a packet
  EXPECT_TRUE(readPacket(new_fd, p));
  ::close(old_fd);
  ::close(new_fd);
}

TEST(LolaServer, AClientThatStopsReadingIsClosed) {
  LolaServer server(socketPath("stall"));
  const int fd = connectUnix(server.path());
  ASSERT_GE(fd, 0);
  // The client never reads: the server's send buffer fills (94 packets with
  // Linux's default 208 KiB, measured), then the client is closed.
  int cycles = 0;
  Exchange e;
  do {
    e = server.exchange(encodeSensorPacket({}), 2ms);
    ++cycles;
  } while (e.status == Status::Timeout && cycles < 5000);
  EXPECT_EQ(e.status, Status::Stalled) << toString(e.status) << " after " << cycles;
  EXPECT_GT(cycles, 1);
  RecordProperty("packets_until_stalled", cycles);
  EXPECT_NE(e.error.find("did not read"), std::string::npos) << e.error;
  EXPECT_FALSE(server.connected());
  ::close(fd);
}

TEST(LolaServer, RefusesAPathThatIsNotASocketAndRemovesItsSocket) {
  const std::string path = socketPath("file");
  FILE* f = std::fopen(path.c_str(), "w");
  std::fclose(f);
  try {
    LolaServer server(path);
    ADD_FAILURE() << "a regular file was replaced";
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("not a socket"), std::string::npos) << e.what();
  }
  ::unlink(path.c_str());
  {
    LolaServer server(path);
    struct stat st{};
    ASSERT_EQ(::lstat(path.c_str(), &st), 0);
    EXPECT_TRUE(S_ISSOCK(st.st_mode));
  }
  {  // a stale socket (bound by an earlier run, nobody listening) is replaced
    const int stale = simswift::testing::bindUnix(path);
    ASSERT_GE(stale, 0);
    ::close(stale);
    LolaServer again(path);
    const int fd = connectUnix(path);
    EXPECT_GE(fd, 0);
    if (fd >= 0) ::close(fd);
  }
  struct stat st{};
  EXPECT_NE(::lstat(path.c_str(), &st), 0);
}

// The facts-only client as its own process, in each of its answer modes.
class LolaClientProcess : public ::testing::TestWithParam<const char*> {};

TEST_P(LolaClientProcess, ReadsCheckedPacketsAndCommandsTheJoints) {
  const std::string mode = GetParam();
  LolaServer server(socketPath(("client-" + mode).c_str()));
  constexpr int kCycles = 20;
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string exe = std::string(SIMSWIFT_BINARY_DIR) + "/lola-client";
    const std::string cycles = std::to_string(kCycles);
    ::execl(exe.c_str(), exe.c_str(), server.path().c_str(), cycles.c_str(), mode.c_str(), nullptr);
    ::_exit(127);
  }
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    // Different values every cycle: the client checks the layout stays.
    SensorPacket sensors = packetWithKnee(0.5f + cycle);
    sensors.fsr[LFootFrontLeft] = 0.1f * cycle;
    sensors.status[HeadYaw] = static_cast<std::uint8_t>(cycle % 4);
    sensors.accelerometer = {0.f, 0.f, -9.81f};
    const Exchange e = server.exchange(encodeSensorPacket(sensors), 10000ms);
    ASSERT_EQ(e.status, Status::Answered) << "cycle " << cycle << ": " << toString(e.status) << " " << e.error;
    ASSERT_TRUE(e.command.stiffness);
    if (mode == "limp") {
      EXPECT_FALSE(e.command.position);
      EXPECT_EQ((*e.command.stiffness)[LKneePitch], 0.f);
      continue;
    }
    // The client commands Position[i] = 0.01 i + 0.001 cycle in LoLA's joint
    // order (B-Human's NaoProvider, HULKs' hula): its index 10 is our
    // LKneePitch, 13 our RHipRoll.
    ASSERT_TRUE(e.command.position);
    EXPECT_NEAR((*e.command.position)[LKneePitch], 0.10f + 0.001f * cycle, 1e-6f);
    EXPECT_NEAR((*e.command.position)[RHipRoll], 0.13f + 0.001f * cycle, 1e-6f);
    EXPECT_NEAR((*e.command.position)[RHand], 0.24f + 0.001f * cycle, 1e-6f);
    EXPECT_EQ((*e.command.stiffness)[HeadYaw], 0.5f);
    // rUNSWift's second map (Sonar) joins the next cycle's answer.
    if (mode == "two-maps" && cycle > 0) {
      ASSERT_TRUE(e.command.sonar);
      EXPECT_EQ(*e.command.sonar, (std::array<bool, 2>{true, false}));
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const Exchange after = server.exchange(encodeSensorPacket({}), 1000ms);
  EXPECT_TRUE(after.status == Status::Disconnected || after.status == Status::NoClient) << toString(after.status);
}

INSTANTIATE_TEST_SUITE_P(Modes, LolaClientProcess, ::testing::Values("one-map", "two-maps", "split", "limp"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });
