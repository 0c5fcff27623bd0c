// The NAO's cameras as V4L2 devices (sim/bridge/V4l2Devices, shim/): the
// facts-only camera probe (tests/team_program/camera_probe.c, no simswift
// header), launched as a V6 robot's program with the facts-only LoLA client
// answering its body, opens /dev/video-top and /dev/video-bottom, streams
// both, and sees the ball where the camera model projects it; two runs see
// the same frames. And the scenario's v4l2: key.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/nao/NaoFacts.hpp"
#include "common/v4l2/DeviceBlock.hpp"
#include "sim/bridge/BodyHost.hpp"
#include "sim/bridge/V4l2Devices.hpp"
#include "sim/runner/Runner.hpp"
#include "tests/support/ConfigErrors.hpp"
#ifdef SIMSWIFT_HAVE_CAMERAS
#include "sim/camera/CameraModel.hpp"
#include "sim/camera/RobotCameras.hpp"
#endif

using simswift::runner::Runner;
using simswift::runner::RobotSpec;
using simswift::runner::Scenario;

namespace {

const std::string kProbe = std::string(SIMSWIFT_BINARY_DIR) + "/camera-probe";
const std::string kClient = std::string(SIMSWIFT_BINARY_DIR) + "/lola-client";
const std::string kV5Client = std::string(SIMSWIFT_BINARY_DIR) + "/libagent2017-client";
constexpr double kBallX = 2.0, kBallY = 0.15;  // m, field frame; the robot at the origin facing +x

// A V6 robot whose launched program is the probe (`frames` frames, `memory`
// buffers) with the LoLA client holding its stand; its own team number per
// test (named objects), its log under /tmp.
// With `v5`: a V5 robot (libagent, 10 ms) whose cameras are /dev/video0
// (top) and /dev/video1 (bottom), the 2017 libagent client holding its pose.
Scenario probeScenario(int team, int frames, const std::string& memory, double duration, bool v5 = false) {
  std::ostringstream y;
  y << "duration: " << duration << "\nseed: 5\nattach_timeout: 20\nball: {x: " << kBallX << ", y: " << kBallY
    << "}\nrobots:\n  - {team: " << team << ", player: 1, x: 0, y: 0, ";
  if (v5)
    y << "libagent: {release: 2017}, program: {command: [\"" << kProbe << "\", /dev/video0, /dev/video1, \"" << frames
      << "\", " << memory << ", \"" << kV5Client << "\", --team, \"{team}\", --player, \"{player}\", --ticks, 100000, "
      << "--hold]}}\n";
  else
    y << "lola: {socket: /tmp/simswift-test-v4l2-" << ::getpid() << "-" << team << "}, program: {command: [\"" << kProbe
      << "\", /dev/video-top, /dev/video-bottom, \"" << frames << "\", " << memory << ", \"" << kClient
      << "\", \"{socket}\", \"0\", hold]}}\n";
  Scenario sc = Scenario::parse(y.str(), std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/v4l2_test.yaml");
  sc.program_logs = "/tmp/simswift-test-v4l2-logs-" + std::to_string(::getpid());
  return sc;
}

struct ProbeLog {
  std::vector<std::map<std::string, std::string>> frames;  // "frame" lines, key=value
  std::map<std::string, std::string> facts;                // other lines' first word -> the line
  std::string digest;
};

std::map<std::string, std::string> fields(const std::string& line) {
  std::map<std::string, std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) {
    const size_t eq = w.find('=');
    if (eq != std::string::npos) out[w.substr(0, eq)] = w.substr(eq + 1);
  }
  return out;
}

ProbeLog readLog(const std::string& path) {
  ProbeLog log;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("frame ", 0) == 0) log.frames.push_back(fields(line));
    else if (line.rfind("done ", 0) == 0) log.digest = fields(line)["digest"];
    else if (line.rfind("packet", 0) != 0) log.facts[line.substr(0, line.find(' '))] += line + "\n";
  }
  return log;
}

simswift::runner::RunOptions quiet() {
  simswift::runner::RunOptions o;
  o.progress = false;
  return o;
}

}  // namespace

TEST(V4l2Scenario, DevicePathsPerBodyAndChecked) {
  const std::string launched = "program: {command: [x]}";
  const Scenario v6 = Scenario::parse("robots:\n  - {team: 19, player: 1, lola: {}, " + launched + "}\n", "a.yaml");
  EXPECT_EQ(v6.robots[0].v4l2.mode, RobotSpec::CameraDevices::Mode::Default);
  EXPECT_EQ(v6.robots[0].v4l2.path[0], "/dev/video-top");
  EXPECT_EQ(v6.robots[0].v4l2.path[1], "/dev/video-bottom");
  const Scenario v5 = Scenario::parse("robots:\n  - {team: 19, player: 1, v4l2: on, " + launched + "}\n", "a.yaml");
  EXPECT_EQ(v5.robots[0].v4l2.mode, RobotSpec::CameraDevices::Mode::On);
  EXPECT_EQ(v5.robots[0].v4l2.path[0], "/dev/video0");
  EXPECT_EQ(v5.robots[0].v4l2.path[1], "/dev/video1");
  const Scenario set = Scenario::parse(
      "robots:\n  - {team: 19, player: 1, v4l2: {top: /dev/cam-a}, " + launched + "}\n", "a.yaml");
  EXPECT_EQ(set.robots[0].v4l2.path[0], "/dev/cam-a");
  EXPECT_EQ(set.robots[0].v4l2.path[1], "/dev/video1");
  using simswift::testing::configError;
  EXPECT_EQ(configError([] { Scenario::parse("robots:\n  - {team: 19, player: 1, v4l2: on}\n", "b.yaml"); }),
            "b.yaml:2: robots[0].v4l2: the cameras as V4L2 devices are for a program of its own (program: {command: "
            "[...]} or external)");
  // An external robot's (a program started by hand) are allowed.
  const Scenario ext = Scenario::parse("robots:\n  - {team: 19, player: 1, lola: {}, program: external, v4l2: off}\n",
                                       "e.yaml");
  EXPECT_EQ(ext.robots[0].v4l2.mode, RobotSpec::CameraDevices::Mode::Off);
  EXPECT_EQ(configError([&] {
              Scenario::parse("robots:\n  - {team: 19, player: 1, " + launched + ",\n     v4l2: {top: video0}}\n",
                              "c.yaml");
            }),
            "c.yaml:3: robots[0].v4l2.top: a camera's device is a path under /dev/ of at most 63 characters (got "
            "'video0')");
  EXPECT_EQ(configError([&] {
              Scenario::parse("robots:\n  - {team: 19, player: 1, " + launched +
                                  ", v4l2: {top: /dev/v, bottom: /dev/v}}\n",
                              "d.yaml");
            }),
            "d.yaml:2: robots[0].v4l2.bottom: the two cameras need two device paths (both are /dev/v)");
}

// What the program writes into its block is read once and checked: a
// value no shim writes ends the run with an error naming the robot and the
// field, never an out-of-range read.
TEST(V4l2Devices, ProgramFieldsAreChecked) {
  simswift::bridge::V4l2Devices d("t76p1", {"/dev/video-top", "/dev/video-bottom"});
  const int fd = ::shm_open(d.blockName().c_str(), O_RDWR, 0);
  ASSERT_GE(fd, 0);
  void* p = ::mmap(nullptr, sizeof(common::v4l2::DeviceBlock), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  ASSERT_NE(p, MAP_FAILED);
  auto* block = static_cast<common::v4l2::DeviceBlock*>(p);  // as the program sees it
  EXPECT_EQ(std::string(block->camera[1].device), "/dev/video-bottom");
  auto request = d.requests();
  EXPECT_FALSE(request[0].publish);
  EXPECT_EQ(request[0].size.width, 640);
  block->camera[0].streaming = 1;
  block->camera[0].buffers_queued = 3;
  block->camera[0].width_wanted = 320;
  block->camera[0].height_wanted = 240;
  request = d.requests();
  EXPECT_TRUE(request[0].publish);
  EXPECT_EQ(request[0].size.height, 240);
  auto error = [&] {
    try {
      d.requests();
    } catch (const simswift::bridge::BridgeError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  block->camera[0].width_wanted = 5000;  // no camera size
  EXPECT_NE(error().find("robot t76p1: its program wrote a format of 5000x240 into camera top"), std::string::npos)
      << error();
  block->camera[0].width_wanted = 320;
  block->camera[1].buffers_queued = -4;
  EXPECT_NE(error().find("buffers_queued = -4 into camera bottom"), std::string::npos) << error();
  block->camera[1].buffers_queued = 0;
  // A frame published, then a taken count past it.
  d.publish(0, 7, 233000, {320, 240});
  EXPECT_EQ(block->camera[0].frames_posted.load(), 1);
  block->camera[0].frames_taken = 9;
  try {
    d.waitTaken(0.01);
    ADD_FAILURE() << "no error";
  } catch (const simswift::bridge::BridgeError& e) {
    EXPECT_NE(std::string(e.what()).find("frames_taken = 9"), std::string::npos) << e.what();
  }
  block->camera[0].frames_taken = 1;
  EXPECT_TRUE(d.waitTaken(0.01));
  ::munmap(p, sizeof(common::v4l2::DeviceBlock));
}

// An external robot's block, named by the robot: served while its
// simulator lives; a killed simulator's (a child that ends without its
// destructor) is not, and `simswift clean`'s removeStale takes only that
// one, with its FIFOs.
TEST(V4l2Devices, AKilledRunsBlockIsNotServedAndCleanRemovesIt) {
  namespace cv = common::v4l2;
  const std::string live_name = cv::blockName("t98p1"), dead_name = cv::blockName("t98p2");
  simswift::bridge::V4l2Devices live("t98p1", {"/dev/video-top", "/dev/video-bottom"}, live_name);
  EXPECT_EQ(live.blockName(), "/simswift-v4l2-t98p1");
  const pid_t pid = ::fork();
  if (pid == 0) {
    new simswift::bridge::V4l2Devices("t98p2", {"/dev/video-top", "/dev/video-bottom"}, dead_name);
    ::_exit(0);  // killed: no destructor, no exit handlers
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_TRUE(simswift::bridge::V4l2Devices::served(live_name));
  EXPECT_FALSE(simswift::bridge::V4l2Devices::served(dead_name));
  EXPECT_EQ(::access(cv::fifoPath(dead_name, "taken").c_str(), F_OK), 0) << "the killed run's FIFOs are left";
  EXPECT_TRUE(simswift::bridge::V4l2Devices::removeStale("t98p1").empty()) << "a served block stays";
  EXPECT_EQ(simswift::bridge::V4l2Devices::removeStale("t98p2"), std::vector<std::string>{dead_name});
  for (const char* which : {"top", "bottom", "taken"})
    EXPECT_NE(::access(cv::fifoPath(dead_name, which).c_str(), F_OK), 0) << which;
  EXPECT_NE(::access(("/dev/shm" + dead_name).c_str(), F_OK), 0);
  EXPECT_TRUE(simswift::bridge::V4l2Devices::served(live_name));
}

#ifdef SIMSWIFT_HAVE_CAMERAS

// MMAP buffers: every answer a team's code checks, 30 Hz of simulated time
// in the buffers' timestamps, each camera at the size it set, the ball
// where the camera model (the renderer's own) projects its centre.
TEST(V4l2Cameras, ProbeStreamsBothCamerasAndSeesTheBall) {
  constexpr int kFrames = 8;
  const Scenario sc = probeScenario(71, kFrames, "mmap", 0.6);
  Runner r(sc);
  r.run(quiet());
  ProbeLog log = readLog(sc.program_logs + "/t71p1.log");
  ASSERT_EQ(log.frames.size(), 2u * kFrames) << log.facts["error"];
  EXPECT_NE(log.facts["open"].find("/dev/video-top chardev=1 driver=uvcvideo"), std::string::npos) << log.facts["open"];
  EXPECT_NE(log.facts["open"].find("/dev/video-bottom chardev=1"), std::string::npos) << log.facts["open"];
  EXPECT_NE(log.facts["format"].find("/dev/video-bottom 320x240 sizeimage=153600 fps=30/1"), std::string::npos);
  EXPECT_EQ(log.facts["control"],
            "control /dev/video-top brightness_max=255 brightness=10 exposure_auto=1 register=0x1234\n");
  EXPECT_EQ(log.facts["unknown_ioctl"], "unknown_ioctl result=-1 errno=25\n");  // ENOTTY
  EXPECT_EQ(log.facts["nonblock_empty"], "nonblock_empty errno=11\n");         // EAGAIN
  std::map<std::string, std::vector<long long>> times;
  for (const auto& f : log.frames) {
    const std::string cam = f.at("cam");
    EXPECT_EQ(std::stoll(f.at("seq")), static_cast<long long>(times[cam].size()));
    times[cam].push_back(std::stoll(f.at("t_us")));
    EXPECT_EQ(f.at("mono"), "1");
    // On the program's own (simulated) CLOCK_MONOTONIC, as a UVC driver
    // stamps buffers: never from the future; read just after DQBUF, which
    // lets the run go on, at most the gap to the next frame old (36 ms at
    // 12 ms ticks): the run cannot pass the next frame's tick before the
    // program takes that frame. (Before this was the clock's base, the
    // buffers were 60 s older than the program's clock.)
    EXPECT_GE(std::stoll(f.at("age_us")), 0) << cam;
    EXPECT_LE(std::stoll(f.at("age_us")), 36000) << cam;
    EXPECT_EQ(f.at("bytes"), cam == "/dev/video-top" ? "614400" : "153600");
  }
  // Frame k is taken at the first 12 ms tick at or after k/30 s: the gaps
  // are 24 or 36 ms, and k frames span k/30 s to within a tick.
  for (const auto& [cam, t] : times) {
    ASSERT_EQ(t.size(), static_cast<size_t>(kFrames)) << cam;
    for (size_t k = 1; k < t.size(); ++k) EXPECT_TRUE(t[k] - t[k - 1] == 24000 || t[k] - t[k - 1] == 36000) << cam;
    EXPECT_NEAR(static_cast<double>(t.back() - t.front()), (kFrames - 1) * 1e6 / 30, 12000.0) << cam;
    EXPECT_EQ(t.front() % 12000, 0) << "a frame's time is its tick's";
  }
  EXPECT_EQ(times["/dev/video-top"], times["/dev/video-bottom"]) << "both cameras' frames are taken together";
  // The ball: the orange pixels' centroid in the last top frame against the
  // projection of the ball's centre with the top camera as the run ends
  // (the robot stands still: less than a pixel between the two). 3 px: the
  // centroid of a sphere's image (about 20 px across at 2 m) is not the
  // projection of its centre, and the orange threshold cuts its shaded rim.
  const simswift::World& w = r.world();
  const simswift::RobotBody& body = w.robot(0);
  const auto camera = simswift::camera::CameraModel::naoCamera(
      body.linkPose(simswift::camera::RobotCameras::headLink(body.model())), simswift::camera::kTop, 640, 480,
      common::nao::kV6CameraLens);
  const auto px = camera.project(w.ballPosition());
  ASSERT_TRUE(px.has_value());
  const auto& last = log.frames[log.frames.size() - 2].at("cam") == "/dev/video-top" ? log.frames[log.frames.size() - 2]
                                                                                      : log.frames.back();
  ASSERT_GT(std::stol(last.at("ball_n")), 50) << "the ball is seen";
  EXPECT_NEAR(std::stod(last.at("ball_x")), px->x(), 3.0);
  EXPECT_NEAR(std::stod(last.at("ball_y")), px->y(), 3.0);
}

// Two runs stream the same frames (the digest of every frame's bytes and
// time); USERPTR buffers get the very frames MMAP buffers got.
TEST(V4l2Cameras, SameFramesRunAfterRunAndWithUserptrBuffers) {
  std::string digest[3];
  for (int k = 0; k < 3; ++k) {
    const Scenario sc = probeScenario(72 + k, 5, k < 2 ? "mmap" : "userptr", 0.4);
    Runner r(sc);
    r.run(quiet());
    ProbeLog log = readLog(sc.program_logs + "/t" + std::to_string(72 + k) + "p1.log");
    EXPECT_EQ(log.frames.size(), 10u) << log.facts["error"];
    digest[k] = log.digest;
  }
  EXPECT_FALSE(digest[0].empty());
  EXPECT_EQ(digest[0], digest[1]);
  EXPECT_EQ(digest[0], digest[2]);
}

// A V5 robot (libagent): the same probe streams /dev/video0 and /dev/video1
// (the V5's names) at 30 Hz of simulated time on 10 ms ticks, MMAP and
// USERPTR buffers giving the same frames, and sees the ball where the V5's
// top camera projects it. The run ends 30 ms after the last frame (0.17 s):
// the V5's body still settles from its start (ending at 0.4 s, the
// projection had moved 3.7 px from the frame's ball).
TEST(V4l2Cameras, AV5RobotStreamsVideo0AndVideo1) {
  constexpr int kFrames = 6;
  std::string digest[2];
  for (int k = 0; k < 2; ++k) {
    const int team = 76 + k;
    const Scenario sc = probeScenario(team, kFrames, k == 0 ? "mmap" : "userptr", 0.2, true);
    Runner r(sc);
    r.run(quiet());
    ProbeLog log = readLog(sc.program_logs + "/t" + std::to_string(team) + "p1.log");
    ASSERT_EQ(log.frames.size(), 2u * kFrames) << log.facts["error"];
    EXPECT_NE(log.facts["open"].find("/dev/video0 chardev=1 driver=uvcvideo"), std::string::npos) << log.facts["open"];
    EXPECT_NE(log.facts["open"].find("/dev/video1 chardev=1"), std::string::npos) << log.facts["open"];
    std::map<std::string, std::vector<long long>> times;
    for (const auto& f : log.frames) times[f.at("cam")].push_back(std::stoll(f.at("t_us")));
    for (const auto& [cam, t] : times) {
      ASSERT_EQ(t.size(), static_cast<size_t>(kFrames)) << cam;
      // Frame k at the first 10 ms tick at or after k/30 s: gaps of 30 or 40 ms.
      for (size_t i = 1; i < t.size(); ++i) EXPECT_TRUE(t[i] - t[i - 1] == 30000 || t[i] - t[i - 1] == 40000) << cam;
      EXPECT_EQ(t.front() % 10000, 0) << "a frame's time is its tick's";
    }
    EXPECT_EQ(times["/dev/video0"], times["/dev/video1"]);
    digest[k] = log.digest;
    if (k == 0) {
      const simswift::World& w = r.world();
      const simswift::RobotBody& body = w.robot(0);
      const auto camera = simswift::camera::CameraModel::naoCamera(
          body.linkPose(simswift::camera::RobotCameras::headLink(body.model())), simswift::camera::kTop, 640, 480,
          common::nao::kV5CameraLens);
      const auto px = camera.project(w.ballPosition());
      ASSERT_TRUE(px.has_value());
      const auto& last = log.frames[log.frames.size() - 2].at("cam") == "/dev/video0" ? log.frames[log.frames.size() - 2]
                                                                                       : log.frames.back();
      ASSERT_GT(std::stol(last.at("ball_n")), 50) << "the ball is seen";
      EXPECT_NEAR(std::stod(last.at("ball_x")), px->x(), 3.0);
      EXPECT_NEAR(std::stod(last.at("ball_y")), px->y(), 3.0);
    }
  }
  EXPECT_FALSE(digest[0].empty());
  EXPECT_EQ(digest[0], digest[1]);
}

// A program started by hand (issue 44): a V6 robot whose program is
// external, the probe started with `simswift attach --team T --player 1`
// (the LoLA client it starts opens /tmp/robocup, attach's), streams both
// cameras as the launched probe does: the same frames at the same
// simulated times (the digest of every frame's bytes and time), 30 Hz of
// simulated time on the ticks. Before, attach handed it no cameras.
TEST(V4l2Cameras, AProgramStartedByHandWithAttachStreamsBothCameras) {
  constexpr int kFrames = 5;
  const Scenario launched_sc = probeScenario(78, kFrames, "mmap", 0.4);
  {
    Runner r(launched_sc);
    r.run(quiet());
  }
  ProbeLog launched = readLog(launched_sc.program_logs + "/t78p1.log");
  ASSERT_EQ(launched.frames.size(), 2u * kFrames) << launched.facts["error"];

  constexpr int kTeam = 79;
  std::ostringstream y;
  y << "duration: 0.4\nseed: 5\nattach_timeout: 20\nball: {x: " << kBallX << ", y: " << kBallY
    << "}\nrobots:\n  - {team: " << kTeam << ", player: 1, x: 0, y: 0, lola: {}, program: external}\n";
  Scenario sc = Scenario::parse(y.str(), std::string(SIMSWIFT_SOURCE_DIR) + "/scenarios/v4l2_test.yaml");
  sc.program_logs = "/tmp/simswift-test-v4l2-logs-" + std::to_string(::getpid());
  const std::string log_path = sc.program_logs + "/attached-t79p1.log";
  ::mkdir(sc.program_logs.c_str(), 0755);
  pid_t pid = -1;
  {
    Runner r(sc);
    r.start();  // the socket, the camera block and the clock page exist from here
    pid = ::fork();
    if (pid == 0) {
      const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) ::dup2(fd, 1), ::dup2(fd, 2);
      std::vector<std::string> args = {std::string(SIMSWIFT_BINARY_DIR) + "/simswift",
                                       "attach",
                                       "--team",
                                       std::to_string(kTeam),
                                       "--player",
                                       "1",
                                       "--",
                                       kProbe,
                                       "/dev/video-top",
                                       "/dev/video-bottom",
                                       std::to_string(kFrames),
                                       "mmap",
                                       kClient,
                                       "/tmp/robocup",
                                       "0",
                                       "hold"};
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    r.run(quiet());
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ProbeLog log = readLog(log_path);
  std::ifstream whole(log_path);
  const std::string text((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
  ASSERT_EQ(log.frames.size(), 2u * kFrames) << text;
  EXPECT_NE(log.facts["open"].find("/dev/video-top chardev=1 driver=uvcvideo"), std::string::npos) << text;
  EXPECT_NE(log.facts["open"].find("/dev/video-bottom chardev=1"), std::string::npos) << text;
  std::map<std::string, std::vector<long long>> times;
  for (const auto& f : log.frames) {
    EXPECT_EQ(f.at("mono"), "1");
    times[f.at("cam")].push_back(std::stoll(f.at("t_us")));
  }
  for (const auto& [cam, t] : times) {
    ASSERT_EQ(t.size(), static_cast<size_t>(kFrames)) << cam;
    // Frame k at the first 12 ms tick at or after k/30 s: gaps of 24 or 36 ms.
    for (size_t k = 1; k < t.size(); ++k) EXPECT_TRUE(t[k] - t[k - 1] == 24000 || t[k] - t[k - 1] == 36000) << cam;
    EXPECT_EQ(t.front() % 12000, 0) << "a frame's time is its tick's";
  }
  EXPECT_EQ(times["/dev/video-top"], times["/dev/video-bottom"]);
  EXPECT_FALSE(log.digest.empty());
  EXPECT_EQ(log.digest, launched.digest) << "the launched probe's frames";
  // The run's block goes with it.
  EXPECT_FALSE(simswift::bridge::V4l2Devices::served(common::v4l2::blockName("t79p1")));
  EXPECT_NE(::access(("/dev/shm" + common::v4l2::blockName("t79p1")).c_str(), F_OK), 0);
}

#endif
