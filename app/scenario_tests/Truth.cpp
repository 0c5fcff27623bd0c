#include "app/scenario_tests/Truth.hpp"

#include <cmath>

#include "sim/runner/Runner.hpp"

namespace simswift::scenario_tests {

Truth observe(runner::Runner& r, double t, const Truth* before) {
  Truth out;
  out.t = t;
  const World& w = r.world();
  out.has_ball = w.hasBall();
  if (out.has_ball) {
    const Eigen::Vector3d b = w.ballPosition();
    out.ball_x = b.x();
    out.ball_y = b.y();
    out.ball_z = b.z();
  }
  const int n = r.numRobots();
  out.robots.resize(n);
  for (int i = 0; i < n; ++i) {
    RobotTruth& rt = out.robots[i];
    const RobotBody::TorsoPose p = w.robot(i).torsoPose();
    rt.side = static_cast<int>(r.scenario().robots[i].colour);
    rt.x = p.x;
    rt.y = p.y;
    rt.heading = p.heading;
    rt.fallen = r.robotFall(i).fallen;
    rt.falls = r.robotFall(i).falls;
    rt.penalised = r.gameController().penalised(i);
    rt.touched_ball = before && i < static_cast<int>(before->robots.size()) && before->robots[i].touched_ball;
  }
  // The contacts of the tick's substeps: a robot link against the ball.
  for (const LinkContact& c : w.contacts())
    if (c.other == GeomTag::Ball && c.robot >= 0 && c.robot < n) out.robots[c.robot].touched_ball = true;
  out.state = r.gameController().state();
  const network::TeamNetworkStats& s = r.teamNetwork().stats();
  // What each team's programs sent, within the budget or not.
  for (int k = 0; k < 2; ++k) out.team_sent[k] = s.team_sent[k] + s.team_over_budget[k];
  return out;
}

bool ballInGoal(const Truth& t, const FieldConfig& f, int side) {
  if (!t.has_ball) return false;
  const double r = f.ball.diameter / 2;
  // The goal line's outer edge; the whole ball beyond it (SPL rules: a goal
  // is scored when the whole ball has crossed the goal line between the posts).
  const double line = f.length / 2 + f.line_width / 2 + r;
  const bool over = side == 0 ? t.ball_x < -line : t.ball_x > line;
  return over && std::fabs(t.ball_y) < f.goal.inner_width / 2 && t.ball_z < f.goal.post_height;
}

}  // namespace simswift::scenario_tests
