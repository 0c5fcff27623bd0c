// Traces one find-ball trial of an experiment file: every `every` s of play,
// per robot, its true torso pose, the pose its behaviour used, its search
// segment and point, and what it has heard of its teammates (pose and the
// segment their packets name); and every robot-robot contact as it starts.
// A diagnosis aid (it asserts nothing):
//   build/tools/findball-trace scenarios/findball_random_starts.yaml 107 [every_s]
// The trial runs as `simswift experiment --trial` runs it (the same scenario,
// hooks and start), without the fallen-robot sideline rule and the found rule
// (the trace runs to the time limit).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "agent/blackboard/FindBallInfo.hpp"
#include "agent/program/RobotProgram.hpp"
#include "sim/programs/Programs.hpp"
#include "app/experiment/BehaviourHooks.hpp"
#include "app/experiment/Experiment.hpp"
#include "app/experiment/Trial.hpp"
#include "sim/world/World.hpp"

using namespace simswift;
using namespace simswift::experiment;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: findball-trace FILE.yaml TRIAL [every_s]\n");
    return 2;
  }
  const Experiment e = Experiment::loadFile(argv[1]);
  const TrialSpec t = trialSpec(e, std::atoi(argv[2]));
  const double every = argc > 3 ? std::atof(argv[3]) : 0.5;
  const TrialHooks hooks = behaviourHooks();
  const std::unique_ptr<runner::Runner> owned = startTrial(e, t.index, hooks);
  runner::Runner& run = *owned;
  const Setup& setup = e.setups[t.setup];
  const int n = static_cast<int>(setup.robots.size());
  std::printf("# trial %d setup %s ball %d (%.2f, %.2f) seed %llu\n", t.index, setup.name.c_str(), t.ball + 1,
              e.balls[t.ball].x, e.balls[t.ball].y, static_cast<unsigned long long>(t.seed));
  const int64_t play = playTick(e);
  const int64_t limit = play + common::nao::ticksIn(e.time_limit);
  const int64_t step = std::max<int64_t>(1, common::nao::ticksIn(every));
  std::vector<int> contacts(n, 0), falls(n, 0);
  while (run.ticks() < limit) {
    run.tick();
    const int64_t tick = run.ticks();
    if (tick < play) continue;
    const double clock = (tick - play) * kTickSeconds;
    const runner::RunStats st = run.stats();
    for (int i = 0; i < n; ++i) {
      if (st.robots[i].falls != falls[i])
        std::printf("%7.2f FALL p%d (contact falls %d)\n", clock, setup.robots[i].player, st.robots[i].contact_falls);
      falls[i] = st.robots[i].falls;
    }
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const auto a = run.world().robot(i).torsoPose(), b = run.world().robot(j).torsoPose();
        const double d = std::hypot(a.x - b.x, a.y - b.y);
        if (d < 0.35 && (tick - play) % 10 == 0)
          std::printf("%7.2f CLOSE p%d-p%d %.3f m\n", clock, setup.robots[i].player, setup.robots[j].player, d);
      }
    if ((tick - play) % step != 0) continue;
    for (int i = 0; i < n; ++i) {
      const auto p = run.world().robot(i).torsoPose();
      const agent::blackboard::FindBallInfo fb = run.programs().program(i)->board().findball.read();
      std::printf("%7.2f p%d true (%6.0f,%6.0f,%5.2f) est (%6.0f,%6.0f,%5.2f) err %4.0f %-14s seg %2d pt (%5.0f,%5.0f) |",
                  clock, setup.robots[i].player, p.x * 1000, p.y * 1000, p.heading, fb.pose_x, fb.pose_y,
                  fb.pose_theta, std::hypot(p.x * 1000 - fb.pose_x, p.y * 1000 - fb.pose_y), fb.activity,
                  fb.segment, fb.point_x, fb.point_y);
      const auto& sv = run.lastSensors(i);
      std::printf(" sonar %.2f %.2f |", sv.sonar[0], sv.sonar[10]);
      for (const auto& m : fb.teammates)
        std::printf(" p%d(%5.0f,%5.0f) s%2d", m.player, m.x, m.y, m.has_target ? m.segment : -1);
      std::printf("\n");
    }
  }
  return 0;
}
