// RunStats formatting. See RunStats.hpp.
#include "sim/runner/RunStats.hpp"

#include <cstdio>
#include <sstream>

namespace simswift::runner {

std::string formatNumber(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string hashHex(uint64_t hash) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

std::string RunStats::summary() const {
  std::ostringstream s;
  s << "sim " << formatNumber("%.2f", sim_s) << " s | wall " << formatNumber("%.2f", wall_s) << " s | "
    << formatNumber("%.1f", real_time_factor) << "x real time | falls " << falls << " | blowups " << blowups;
  if (nan_commands || clamped_angles || clamped_stiffness)
    s << " | nan " << nan_commands << " clamped " << clamped_angles << "+" << clamped_stiffness;
  if (skipped_cycles) s << " | skipped " << skipped_cycles;
  if (gc_udp_sent || gc_udp_failed || !gc_returns.empty()) {
    s << " | gc udp " << gc_udp_sent << " sent";
    if (gc_udp_failed) s << " (" << gc_udp_failed << " failed)";
    for (size_t i = 0; i < gc_returns.size(); ++i)
      s << (i == 0 ? ", returns " : " ") << "t" << gc_returns[i].team << "p" << gc_returns[i].player << " "
        << gc_returns[i].packets;
  }
  s << " | hash " << hashHex(hash);
  return s.str();
}

std::string RunStats::robotLines() const {
  std::ostringstream s;
  for (const RobotEnd& r : robots)
    s << "  t" << r.team << "p" << r.player << ": x " << formatNumber("%.3f", r.x) << " m  y " << formatNumber("%.3f", r.y)
      << " m  theta " << formatNumber("%.3f", r.theta) << " rad  falls " << r.falls << (r.down ? "  down" : "  up") << "\n";
  return s.str();
}

}  // namespace simswift::runner
