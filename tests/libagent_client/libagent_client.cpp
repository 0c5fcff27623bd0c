// A robot program as a team would bring it: it knows nothing of simswift.
// It declares the libagent block itself, from the byte layout of the public
// rUNSWift release it is built for (LIBAGENT_RELEASE = 2016, 2017 or 2018;
// on purpose no project header, so a drift of simswift's blocks from the
// published ones breaks the tests that run it), opens the objects by that
// release's names and does only what libagent's clients do:
//   sem_wait; sensors_read = sensors_latest; read that slot;
//   pick a slot with the Effector's loop; write it; clear `standing`;
//   actuators_latest = slot.
// Names: 2016 has only the robot build (/libagent-memory, opened without
// O_CREAT: the body side must exist first); 2017 N = team x 11 + player;
// 2018 N = team x 6 + player (both opened with O_CREAT, either side first).
//
// Motion: holds the joint angles it measured on its first tick, then a
// scripted head and leg move (ticks counted from its first tick):
//   HeadYaw    ramps 0 -> +0.5 rad over ticks 50..100 (relative to the start)
//   knee bend  d ramps 0 -> 0.2 rad over ticks 100..200, back to 0 over
//              250..350: knees +2d, hips and ankles -d (both legs)
// tests/runner/test_runner_libagent.cpp runs the same moves in-process.
//
//   libagent<R>-client --team T --player P [--bare] --ticks N [--hold]
//                      [--stand] [--sleep-at K MS] [--timeout S] [--print-fsr]
//                      [--print-standing] [--stiffen-at K] [--crash-at K]
//
// --hold: no scripted move, only hold the first tick's angles. --stand:
// hold the NAO's stand instead (knees 0.8, hips and ankles -0.4 rad).
// --print-fsr: print the mean sum of the eight FSRs (kg) over the last 100
// ticks. --print-standing: print "standing K 0|1" for the first ticks and
// every change. --stiffen-at K: send STIFFEN with tick K's command (not in 2016).
//
// It answers N ticks and exits 0; with --timeout S it gives up (exit 3)
// when no tick comes for S wall-clock seconds; --sleep-at K MS sleeps MS ms
// before answering tick K (a program missing cycles); --crash-at K dies of
// SIGSEGV instead of answering tick K (a crashing program).
#ifndef LIBAGENT_RELEASE
#define LIBAGENT_RELEASE 2017
#endif
#include <fcntl.h>
#include <semaphore.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

namespace {

// ---- The 2017 block, as the public rUNSWift 2017 release declares it (its
// AgentData, AgentTouch, AgentEffector; x86-64 offsets in the comments).
struct JointValues {
  float angles[25];
  float stiffnesses[25];
  float temperatures[25];
  float currents[25];
};
struct SensorValues {
  JointValues joints;
  float sensors[37];
  float sonar[20];
};
struct RGB {
  bool red, green, blue;
};
struct LED {
  uint16_t leftEar, rightEar;
  RGB leftEye, rightEye, chestButton, leftFoot, rightFoot;
};
enum StiffenCommand { NONE = 0, STIFFEN };
#if LIBAGENT_RELEASE == 2016
constexpr int kSayLength = 35;
#elif LIBAGENT_RELEASE == 2018
constexpr int kSayLength = 70;
#else
constexpr int kSayLength = 35;
#endif
struct AgentData {
  volatile uint8_t sensors_read;      // 0
  volatile uint8_t sensors_latest;    // 1
  volatile uint8_t actuators_latest;  // 2
  volatile uint8_t actuators_read;    // 3
  SensorValues sensors[3];            // 4
  uint8_t buttons[3];                 // 1888
  JointValues joints[3];              // 1892
  LED leds[3];                        // 3092
  float sonar[3];                     // 3152
#if LIBAGENT_RELEASE != 2016
  StiffenCommand stiffen[3];          // 3164
#endif
  char sayTexts[3][kSayLength];       // 2016: 3164; 2017, 2018: 3176
  volatile bool standing;             // 2016: 3269; 2017: 3281; 2018: 3386
};
#if LIBAGENT_RELEASE == 2016
static_assert(sizeof(AgentData) == 3272, "the 2016 block is 3272 bytes");
#elif LIBAGENT_RELEASE == 2018
static_assert(sizeof(AgentData) == 3388, "the 2018 block is 3388 bytes");
#else
static_assert(sizeof(AgentData) == 3284, "the 2017 block is 3284 bytes");
#endif
const std::string kName = "libagent" + std::to_string(LIBAGENT_RELEASE) + "-client";

// Joint slots used by the script (libagent order).
enum { HeadYaw = 0, LHipPitch = 10, LKneePitch = 11, LAnklePitch = 12, RHipPitch = 15, RKneePitch = 16,
       RAnklePitch = 17 };
// FSR sensor slots: four per foot from these.
enum { LFsrFirst = 14, RFsrFirst = 20 };

// 0 before t0, 1 after t1, linear in between.
float ramp(long k, long t0, long t1) {
  if (k <= t0) return 0.0f;
  if (k >= t1) return 1.0f;
  return static_cast<float>(k - t0) / static_cast<float>(t1 - t0);
}

[[noreturn]] void usage(const char* msg) {
  std::fprintf(stderr, "%s: %s\n", kName.c_str(), msg);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  int team = -1, player = -1;
  bool bare = LIBAGENT_RELEASE == 2016, print_fsr = false, hold_only = false, stand = false, print_standing = false;
  long ticks = -1, sleep_at = -1, sleep_ms = 0, stiffen_at = -1, crash_at = -1;
  double timeout_s = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) usage("missing value");
      return argv[++i];
    };
    if (a == "--team") team = std::atoi(next());
    else if (a == "--player") player = std::atoi(next());
    else if (a == "--bare") bare = true;
    else if (a == "--ticks") ticks = std::atol(next());
    else if (a == "--sleep-at") {
      sleep_at = std::atol(next());
      sleep_ms = std::atol(next());
    } else if (a == "--timeout") timeout_s = std::atof(next());
    else if (a == "--print-fsr") print_fsr = true;
    else if (a == "--hold") hold_only = true;
    else if (a == "--stand") hold_only = stand = true;
    else if (a == "--print-standing") print_standing = true;
    else if (a == "--stiffen-at") stiffen_at = std::atol(next());
    else if (a == "--crash-at") crash_at = std::atol(next());
    else usage(("unknown argument " + a).c_str());
  }
  if (ticks < 0 || (!bare && (team < 0 || player < 1))) usage("need --team, --player (or --bare) and --ticks");

  // The simulation build's names: N = team x 11 (2018: x 6) + player, no separator.
  const int factor = LIBAGENT_RELEASE == 2018 ? 6 : 11;
  const std::string suffix = bare ? "" : std::to_string(team * factor + player);
  const std::string mem_name = "/libagent-memory" + suffix, sem_name = "/libagent-semaphore" + suffix;
  // 2016 opens libagent's objects without O_CREAT: they must exist already.
  const int create = LIBAGENT_RELEASE == 2016 ? 0 : O_CREAT;
  const int fd = shm_open(mem_name.c_str(), create | O_RDWR, 0600);
  if (fd < 0) {
    if (errno == ENOENT && !create) {
      std::fprintf(stderr,
                   "%s: %s does not exist: the body side (libagent on a NAO, simswift here) must be up before a "
                   "2016 robot program starts, which opens its objects without O_CREAT\n",
                   kName.c_str(), mem_name.c_str());
      return 4;
    }
    std::perror(("shm_open " + mem_name).c_str());
    return 1;
  }
  void* p = mmap(nullptr, sizeof(AgentData), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) {
    std::perror("mmap");
    return 1;
  }
  sem_t* sem = create ? sem_open(sem_name.c_str(), O_CREAT, 0600, 0) : sem_open(sem_name.c_str(), 0);
  if (sem == SEM_FAILED) {
    std::perror(("sem_open " + sem_name).c_str());
    return 1;
  }
  AgentData* block = static_cast<AgentData*>(p);
  std::fprintf(stderr, "%s: opened %s and %s\n", kName.c_str(), mem_name.c_str(), sem_name.c_str());
  int last_standing = -1;

  JointValues hold{};
  double fsr_sum = 0;
  long fsr_n = 0;
  for (long k = 1; k <= ticks; ++k) {
    // Touch: wait for the body's cycle.
    if (timeout_s > 0) {
      timespec deadline{};
      clock_gettime(CLOCK_REALTIME, &deadline);
      deadline.tv_sec += static_cast<time_t>(timeout_s);
      int r;
      while ((r = sem_timedwait(sem, &deadline)) != 0 && errno == EINTR) {
      }
      if (r != 0) {
        std::fprintf(stderr, "%s: no tick for %.1f s after %ld ticks: stopping\n", kName.c_str(), timeout_s, k - 1);
        return 3;
      }
    } else {
      while (sem_wait(sem) != 0 && errno == EINTR) {
      }
    }
    if (k == crash_at) {
      std::fprintf(stderr, "%s: crashing at tick %ld (--crash-at)\n", kName.c_str(), k);
      std::fflush(stderr);
      std::signal(SIGSEGV, SIG_DFL);  // not a sanitizer's handler: die of the signal itself
      std::raise(SIGSEGV);
    }
    block->sensors_read = block->sensors_latest;
    const SensorValues s = block->sensors[block->sensors_read];
    const int standing_now = block->standing ? 1 : 0;
    if (print_standing && (k <= 3 || standing_now != last_standing))
      std::printf("standing %ld %d\n", k, standing_now);
    last_standing = standing_now;

    // Motion.
    if (k == 1) {
      hold = s.joints;
      for (float& st : hold.stiffnesses) st = 1.0f;
      if (stand) {
        for (float& a : hold.angles) a = 0.0f;
        for (int hip : {LHipPitch, RHipPitch}) hold.angles[hip] = -0.4f;
        for (int knee : {LKneePitch, RKneePitch}) hold.angles[knee] = 0.8f;
        for (int ankle : {LAnklePitch, RAnklePitch}) hold.angles[ankle] = -0.4f;
      }
    }
    JointValues cmd = hold;
    if (!hold_only) {
      cmd.angles[HeadYaw] = hold.angles[HeadYaw] + 0.5f * ramp(k, 50, 100);
      const float d = 0.2f * (ramp(k, 100, 200) - ramp(k, 250, 350));
      for (int hip : {LHipPitch, RHipPitch}) cmd.angles[hip] = hold.angles[hip] - d;
      for (int knee : {LKneePitch, RKneePitch}) cmd.angles[knee] = hold.angles[knee] + 2.0f * d;
      for (int ankle : {LAnklePitch, RAnklePitch}) cmd.angles[ankle] = hold.angles[ankle] - d;
    }
    if (print_fsr && k > ticks - 100) {
      float sum = 0;
      for (int f = 0; f < 4; ++f) sum += s.sensors[LFsrFirst + f] + s.sensors[RFsrFirst + f];
      fsr_sum += sum;
      ++fsr_n;
    }
    if (k == sleep_at) {
      timespec nap{sleep_ms / 1000, (sleep_ms % 1000) * 1000000L};
      nanosleep(&nap, nullptr);
    }

    // Effector: the release's slot loop (it may stop on the read slot).
    int i = 0;
    for (; i != block->actuators_latest && i != block->actuators_read; ++i) {
    }
    block->joints[i] = cmd;
    block->leds[i] = LED{};
    block->sonar[i] = 0.0f;
#if LIBAGENT_RELEASE != 2016
    block->stiffen[i] = k == stiffen_at ? STIFFEN : NONE;
#endif
    block->sayTexts[i][0] = '\0';
    if (block->standing) block->standing = false;
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    block->actuators_latest = static_cast<uint8_t>(i);
  }
  if (print_fsr && fsr_n > 0) std::printf("fsr-sum-kg %.4f\n", fsr_sum / fsr_n);
  std::fprintf(stderr, "%s: answered %ld ticks\n", kName.c_str(), ticks);
  munmap(p, sizeof(AgentData));
  sem_close(sem);
  return 0;
}
