#include "app/experiment/ProgressLine.hpp"

#include <cmath>
#include <cstdio>

namespace simswift::experiment {

std::string formatDuration(double s) {
  char buf[32];
  if (s < 0 || !std::isfinite(s)) return "?";
  const long t = std::lround(s);
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  return buf;
}

void ProgressLine::trial(const TrialResult& r) {
  char what[200];
  const std::string cell = r.cell >= 0 ? "cell " + std::to_string(r.cell) + ", " : "";
  std::snprintf(what, sizeof what, "trial %d (%s%s, pos %d, #%d): %s | %.1fx real time per core", r.trial, cell.c_str(),
                r.setup.c_str(), r.position, r.repeat + 1,
                r.found ? ("found in " + fixed(r.seconds, 2) + " s by " + r.finder).c_str() : "not found",
                r.realTimeFactor());
  step(what);
}

void ProgressLine::step(const std::string& what) {
  ++done;
  ++ran;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double eta = elapsed / ran * (total - done);  // s, at this run's pace
  if (bar) {
    const int w = 30, fill = total ? done * w / total : w;
    std::fprintf(stderr, "\r\033[K[%s%s] %d/%d  ETA %s  %s", std::string(fill, '#').c_str(),
                 std::string(w - fill, '.').c_str(), done, total, formatDuration(eta).c_str(), what.c_str());
    std::fflush(stderr);
  } else if (lines) {
    std::fprintf(stderr, "%d/%d %s | ETA %s\n", done, total, what.c_str(), formatDuration(eta).c_str());
  }
}

void ProgressLine::fail(int t, const std::string& why) {
  ++failed;
  if (bar) std::fprintf(stderr, "\r\033[K");
  std::fprintf(stderr, "trial %d failed: %s\n", t, why.c_str());
}

void ProgressLine::end() {
  if (bar) std::fprintf(stderr, "\n");
}

}  // namespace simswift::experiment
