#include "app/experiment/FolderFigures.hpp"

#include <cstdio>
#include <map>
#include <sstream>

#include "common/libagent/SharedNames.hpp"
#include "app/experiment/Figures.hpp"
#include "app/experiment/Files.hpp"

namespace simswift::experiment {

namespace {

// Every robot's track samples per setup, from tracks.csv's text (rows:
// trial,setup,player,t,x,y,theta; m, field frame). Rows that do not parse
// (a setup name longer than 127 characters included) are skipped.
std::vector<std::vector<RouteSamples>> routesOf(const Experiment& e, const std::string& tracks) {
  std::map<std::string, int> setup_index;
  for (size_t s = 0; s < e.setups.size(); ++s) setup_index[e.setups[s].name] = static_cast<int>(s);
  std::vector<std::vector<RouteSamples>> routes(e.setups.size());
  for (size_t s = 0; s < e.setups.size(); ++s)
    for (const ExperimentRobot& r : e.setups[s].robots)
      routes[s].push_back({common::libagent::robotTag(r.team, r.player), {}});
  std::istringstream in(tracks);
  std::string line;
  std::getline(in, line);  // header
  char setup[128], player[32];
  double t, x, y, th;
  int trial;
  while (std::getline(in, line)) {
    if (std::sscanf(line.c_str(), "%d,%127[^,],%31[^,],%lf,%lf,%lf,%lf", &trial, setup, player, &t, &x, &y, &th) != 7)
      continue;
    auto it = setup_index.find(setup);
    if (it == setup_index.end()) continue;
    for (RouteSamples& rs : routes[it->second])
      if (rs.player == player) rs.xy.push_back({x, y});
  }
  return routes;
}

}  // namespace

void writeSetupFigures(const Experiment& e, const std::string& dir, const std::vector<TrialResult>& results,
                       const std::string& tracks, std::string* notes) {
  makeDir(dir + "/figures");
  const std::vector<std::vector<RouteSamples>> routes = routesOf(e, tracks);
  for (size_t s = 0; s < e.setups.size(); ++s) {
    drawRoutes(e, static_cast<int>(s), routes[s], dir + "/figures/routes_" + e.setups[s].name + ".png");
    std::string msg;
    if (!plotFindTimes(e, static_cast<int>(s), results, dir + "/figures", &msg) && notes) *notes += msg + "\n";
  }
}

void writeSweepFigures(const Experiment& e, const std::string& dir, const std::vector<CellRow>& rows,
                       std::string* notes) {
  for (size_t k = 0; k < e.sweep.size(); ++k) {
    std::string msg;
    if (!plotSweep(e, rows, static_cast<int>(k), dir + "/figures", &msg) && notes) *notes += msg + "\n";
  }
}

}  // namespace simswift::experiment
