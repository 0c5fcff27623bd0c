// Seeded, in-process mutation fuzzer over the three loaders (URDF, field,
// scenario). Each case takes a shipped input, applies 1-4 random mutations
// (numbers replaced by extremes, lines deleted/duplicated/swapped, bytes
// flipped, deep nesting, truncation, rarely growth to 0.25-3 MB) and runs it
// through FuzzCases.hpp.
//
//   fuzz_loaders [--cases N] [--seed S] [--only K] [--timeout S] [--dump DIR]
//
// N cases in total, spread round-robin over the loaders; case k uses the
// random stream seeded by (S, k), so `--only k` replays one case. Exit 0 when
// every case was accepted or refused with "<file>:<line>: "; 1 on an error
// without a file; 3 on a hang (a case over --timeout s of CPU time, default
// 10, or 12x that of wall clock); a crash
// ends the process (the case number is printed first).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <pthread.h>
#include <time.h>
#include <unistd.h>

#include "FuzzCases.hpp"
#include "common/random/DeriveSeed.hpp"

using namespace simswift::fuzz;

namespace {

// Values that broke loaders or ODE before, and their neighbours.
const char* const kExtremes[] = {
    "0",    "-0",   "1e308", "-1e308", "1e-300", "nan",  "inf",  "-inf", ".nan", ".inf", "1e150",
    "2e154", "1.5", "-1",    "1e12",   "9e16",   "0.04", "0.001", "18446744073709551616", "1e30",
    "",     "abc",  "1e100", "1e305",  "-1e-9",  "3.5",  "100",  "2147483648", "0x10", "1,2"};

struct Mutator {
  std::mt19937_64 rng;
  explicit Mutator(uint64_t seed) : rng(seed) {}
  size_t below(size_t n) { return n ? std::uniform_int_distribution<size_t>(0, n - 1)(rng) : 0; }

  // Start and length of a random number-looking token.
  bool findNumber(const std::string& s, size_t& b, size_t& len) {
    for (int tries = 0; tries < 50; ++tries) {
      size_t i = below(s.size());
      while (i < s.size() && !(std::isdigit(static_cast<unsigned char>(s[i])))) ++i;
      if (i >= s.size()) continue;
      b = i;
      while (b > 0 && (std::isdigit(static_cast<unsigned char>(s[b - 1])) || s[b - 1] == '.' || s[b - 1] == '-' ||
                       s[b - 1] == 'e'))
        --b;
      size_t e = i;
      while (e < s.size() && (std::isdigit(static_cast<unsigned char>(s[e])) || s[e] == '.' || s[e] == 'e' ||
                              s[e] == '-' || s[e] == '+'))
        ++e;
      len = e - b;
      return true;
    }
    return false;
  }

  std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    size_t p = 0;
    while (p <= s.size()) {
      const size_t e = s.find('\n', p);
      out.push_back(s.substr(p, e == std::string::npos ? std::string::npos : e - p));
      if (e == std::string::npos) break;
      p = e + 1;
    }
    return out;
  }
  static std::string join(const std::vector<std::string>& ls) {
    std::string s;
    for (size_t i = 0; i < ls.size(); ++i) s += ls[i] + (i + 1 < ls.size() ? "\n" : "");
    return s;
  }

  // Grows `s` to 0.25-3 MB: one line repeated, or (one time in four) made
  // that long. Any input must be read or refused in time linear in its size
  // (a 3 MB URDF with a NUL byte near its end once took 33 s).
  void grow(std::string& s) {
    auto ls = lines(s);
    const size_t i = below(ls.size());
    const size_t target = (size_t{256} << 10) + below(size_t{3} << 20);  // bytes
    if (ls[i].empty()) ls[i] = "x";
    const std::string unit = ls[i];
    if (below(4) == 0) {
      while (ls[i].size() < target) ls[i] += unit;
    } else {
      const size_t copies = std::min<size_t>(target / (unit.size() + 1), 200000);
      ls.insert(ls.begin() + static_cast<long>(i), copies, unit);
    }
    s = join(ls);
  }

  void mutate(std::string& s) {
    if (s.empty()) s = "x";
    if (below(40) == 0) {  // rare: large inputs cost time in every loader
      grow(s);
      return;
    }
    switch (below(10)) {
      case 0: case 1: case 2: case 3: {  // a number becomes an extreme (the most telling mutation)
        size_t b, len;
        if (findNumber(s, b, len)) s.replace(b, len, kExtremes[below(std::size(kExtremes))]);
        break;
      }
      case 4: {  // delete a line
        auto ls = lines(s);
        ls.erase(ls.begin() + static_cast<long>(below(ls.size())));
        s = join(ls);
        break;
      }
      case 5: {  // duplicate a line
        auto ls = lines(s);
        const size_t i = below(ls.size());
        ls.insert(ls.begin() + static_cast<long>(below(ls.size())), ls[i]);
        s = join(ls);
        break;
      }
      case 6: {  // swap two lines
        auto ls = lines(s);
        std::swap(ls[below(ls.size())], ls[below(ls.size())]);
        s = join(ls);
        break;
      }
      case 7: {  // flip, insert or delete bytes
        const size_t i = below(s.size());
        const int op = static_cast<int>(below(3));
        const char c = static_cast<char>(below(256));
        if (op == 0) s[i] = c;
        else if (op == 1) s.insert(s.begin() + static_cast<long>(i), c);
        else s.erase(i, 1 + below(8));
        break;
      }
      case 8: {  // deep nesting, XML or YAML flavoured
        const size_t depth = 1 + below(below(2) ? 200000 : 100);
        std::string open, close;
        const int kind = static_cast<int>(below(3));
        for (size_t k = 0; k < depth; ++k) {
          open += kind == 0 ? "<a>" : kind == 1 ? "[" : "{a: ";
          close += kind == 0 ? "</a>" : kind == 1 ? "]" : "}";
        }
        s.insert(below(s.size()), open + close);
        break;
      }
      default:  // truncate
        s.resize(below(s.size() + 1));
    }
  }
};

std::atomic<long> g_case{-1};
std::atomic<int64_t> g_case_start_ms{0};   // wall clock
std::atomic<int64_t> g_case_start_cpu{0};  // the fuzzing thread's CPU time (ms)
clockid_t g_main_cpu_clock;

int64_t cpuMs() {
  timespec ts{};
  clock_gettime(g_main_cpu_clock, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}
const char* g_loader = "";

int64_t nowMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void onCrash(int sig) {
  char buf[160];
  const int n = std::snprintf(buf, sizeof buf, "\nfuzz_loaders: CRASH (signal %d) in case %ld (%s)\n", sig,
                              g_case.load(), g_loader);
  if (n > 0) (void)!write(2, buf, static_cast<size_t>(n));
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

int main(int argc, char** argv) {
  long cases = 3000, only = -1;
  uint64_t seed = 1;
  double timeout_s = 10;
  std::string dump;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--cases") cases = std::atol(argv[i + 1]);
    else if (a == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
    else if (a == "--only") only = std::atol(argv[i + 1]);
    else if (a == "--timeout") timeout_s = std::atof(argv[i + 1]);
    else if (a == "--dump") dump = argv[i + 1];
    else {
      std::fprintf(stderr, "usage: fuzz_loaders [--cases N] [--seed S] [--only K] [--timeout S] [--dump DIR]\n");
      return 2;
    }
  }
  for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, onCrash);

  // Hang detector: a case using more than the timeout of CPU time (a loop),
  // or 12x that of wall clock (a wait), ends the run. CPU time, because a
  // loaded CI machine stretches wall time of honest cases.
  pthread_getcpuclockid(pthread_self(), &g_main_cpu_clock);
  std::atomic<bool> done{false};
  std::thread watchdog([&] {
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const int64_t start = g_case_start_ms.load(), start_cpu = g_case_start_cpu.load();
      if (start && (cpuMs() - start_cpu > timeout_s * 1000 || nowMs() - start > 12 * timeout_s * 1000)) {
        std::fprintf(stderr, "fuzz_loaders: HANG: case %ld (%s) over %.0f s of CPU time\n", g_case.load(), g_loader,
                     timeout_s);
        std::fflush(stderr);
        _exit(3);
      }
    }
  });

  const Loader loaders[] = {Loader::Urdf, Loader::Field, Loader::Scenario};
  std::string seeds[3];
  for (int i = 0; i < 3; ++i) seeds[i] = seedText(loaders[i]);
  long counts[3][3] = {};  // loader x outcome
  int64_t slowest_ms = 0;
  long errors = 0;
  for (long k = (only >= 0 ? only : 0); k < (only >= 0 ? only + 1 : cases); ++k) {
    const int li = static_cast<int>(k % 3);
    Mutator m(common::random::deriveSeed(seed, static_cast<uint64_t>(k)));
    std::string text = seeds[li];
    const size_t n = 1 + m.below(4);
    for (size_t j = 0; j < n; ++j) m.mutate(text);
    if (!dump.empty()) std::ofstream(dump + "/case" + std::to_string(k) + "." + loaderName(loaders[li])) << text;
    g_loader = loaderName(loaders[li]);
    g_case = k;
    const int64_t t0 = cpuMs();
    g_case_start_cpu = t0;
    g_case_start_ms = nowMs();
    const CaseResult r = runCase(loaders[li], text);
    g_case_start_ms = 0;
    slowest_ms = std::max(slowest_ms, cpuMs() - t0);
    ++counts[li][static_cast<int>(r.outcome)];
    if (r.outcome == Outcome::ErrorWithoutFile) {
      ++errors;
      std::fprintf(stderr, "fuzz_loaders: ERROR WITHOUT FILE:LINE in case %ld (%s): %s\n", k, g_loader,
                   r.message.substr(0, 300).c_str());
    }
    if (only >= 0) std::printf("case %ld (%s): %s\n", k, g_loader, r.message.c_str());
  }
  done = true;
  watchdog.join();
  long total = 0;
  for (int i = 0; i < 3; ++i) {
    std::printf("fuzz_loaders %-8s accepted %5ld  refused %5ld  error-without-file %ld\n", loaderName(loaders[i]),
                counts[i][0], counts[i][1], counts[i][2]);
    total += counts[i][0] + counts[i][1] + counts[i][2];
  }
  std::printf("fuzz_loaders: %ld cases (seed %llu): crashes 0, hangs 0, errors without a file %ld; slowest case %lld ms CPU\n",
              total, static_cast<unsigned long long>(seed), errors, static_cast<long long>(slowest_ms));
  return errors ? 1 : 0;
}
