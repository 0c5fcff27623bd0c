// The NAO V6 over LoLA against the NAO V5 over libagent (issue 33):
//   lola.handover_us_per_tick     one LoLA cycle's hand-over, wall us: the
//                                 simulator's sensor slot turned into the
//                                 896-byte packet, sent over the Unix
//                                 socket, the client's actuator map (all
//                                 eleven keys, 786 bytes) read back and
//                                 decoded; the client a thread that answers
//                                 at once (no physics)
//   v5|v6.standing_N_robot(s).realtime_factor
//                                 whole runs of N = 1 and 3 standing robots
//                                 with the builtin reference program (inline;
//                                 Motion holds the stand, Perception runs),
//                                 simulated s per wall s: the V5 over
//                                 libagent at 10 ms, the V6 over LoLA at 12 ms
//   v6.client.standing_N_robot(s).realtime_factor
//                                 the same V6 runs with the facts-only LoLA
//                                 client (tests/lola_client) launched per
//                                 robot instead, holding its joints: a
//                                 program in another process that does
//                                 almost nothing
//
// Usage: bench_lola [SIM_SECONDS=10] ; figures are printed and appended to
// the results file (bench/BenchResults.hpp).
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>

#include "BenchResults.hpp"
#include "common/nao/Postures.hpp"
#include "sim/lola/LolaBody.hpp"
#include "sim/programs/Programs.hpp"
#include "sim/runner/Runner.hpp"

using namespace simswift;
using Clock = std::chrono::steady_clock;

namespace {

double handoverMicroseconds(int cycles) {
  const std::string path = "/tmp/simswift-bench-lola-" + std::to_string(::getpid());
  lola::LolaServer server(path);
  std::thread client([&] {
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::snprintf(a.sun_path, sizeof a.sun_path, "%s", path.c_str());
    while (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    lola::ActuatorCommand all;  // every key, as HULKs' client sends them
    all.position.emplace();
    all.stiffness.emplace();
    all.chest.emplace();
    all.lfoot.emplace();
    all.rfoot.emplace();
    all.leye.emplace();
    all.reye.emplace();
    all.lear.emplace();
    all.rear.emplace();
    all.skull.emplace();
    all.sonar.emplace();
    const std::string answer = lola::encodeActuatorMap(all);
    char packet[lola::kSensorPacketBytes];
    for (;;) {
      size_t got = 0;
      while (got < sizeof packet) {
        const ssize_t n = ::read(fd, packet + got, sizeof packet - got);
        if (n <= 0) {
          ::close(fd);
          return;
        }
        got += static_cast<size_t>(n);
      }
      if (::write(fd, answer.data(), answer.size()) != static_cast<ssize_t>(answer.size())) break;
    }
    ::close(fd);
  });
  common::libagent::SensorValues values{};
  values.joints = common::nao::postureCommand(common::nao::Posture::Stand);
  const lola::LolaBodyOptions options;
  auto cycle = [&] {
    const lola::Exchange e =
        server.exchange(lola::encodeSensorPacket(lola::toLolaPacket(values, options)), std::chrono::seconds(5));
    if (e.status != lola::Exchange::Status::Answered) {
      std::fprintf(stderr, "bench_lola: exchange %s\n", lola::toString(e.status));
      std::exit(1);
    }
  };
  for (int i = 0; i < 200; ++i) cycle();  // warm up (and the client connects)
  const Clock::time_point t0 = Clock::now();
  for (int i = 0; i < cycles; ++i) cycle();
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / cycles;
  server.dropClient();
  client.join();
  return us;
}

enum class Case { V5, V6, V6Client };

double realtimeFactor(Case c, int robots, double seconds) {
  std::ostringstream y;
  y << "duration: " << seconds << "\nseed: 1\nnoise: on\nprogram_logs: /tmp/simswift-bench-lola-logs\nrobots:\n";
  for (int r = 0; r < robots; ++r) {
    y << "  - {team: 19, player: " << r + 1 << ", x: -2.0, y: " << -1.0 + r << ", posture: stand";
    if (c != Case::V5) y << ", lola: {socket: /tmp/simswift-bench-lola-" << ::getpid() << "-" << r << "}";
    if (c == Case::V6Client)
      y << ", program: {command: [\"" << SIMSWIFT_BINARY_DIR << "/lola-client\", \"{socket}\", \"0\", hold]}";
    y << "}\n";
  }
  runner::Runner run(runner::Scenario::parse(y.str(), "bench_lola.yaml"));
  run.programs().setThreading(agent::program::Threading::Inline);
  runner::RunOptions o;
  o.progress = false;
  return run.run(o).real_time_factor;
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 10.0;
  std::printf("simswift LoLA benchmark: %.0f simulated s per run, 20000 hand-overs\n", seconds);
  bench::report("lola.handover_us_per_tick", handoverMicroseconds(20000), "us");
  for (int n : {1, 3})
    for (Case c : {Case::V5, Case::V6, Case::V6Client}) {
      char name[64];
      std::snprintf(name, sizeof name, "%s.standing_%d_robot%s.realtime_factor",
                    c == Case::V5 ? "v5" : c == Case::V6 ? "v6" : "v6.client", n, n > 1 ? "s" : "");
      bench::report(name, realtimeFactor(c, n, seconds), "x");
    }
  return 0;
}
