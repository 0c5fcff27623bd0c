// LOGIC TESTS (kinematic world, no physics): the 2016 FindBall in the era's
// manner, the 2017 stop's spin angle, one searcher per segment and the
// walk's keep-out round teammates.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "harness/KinematicWorld.hpp"
#include "harness/Table51Setup.hpp"
#include "agent/behaviour/DistributedUtilityCalculator.hpp"
#include "agent/behaviour/SimpleUtilityCalculator.hpp"
#include "agent/behaviour/SonarFilter.hpp"

using namespace agent::behaviour;
using namespace agent::behaviour::table51;
using agent::blackboard::ActionType;

namespace {
// 1-based table 2.1 number of the robot's current 2016 point.
int pointNumber(const BehaviourConfig& c, Point2 p) {
  for (int k = 0; k < static_cast<int>(c.search.points_2016.size()); ++k)
    if (p.x == c.search.points_2016[k].x && p.y == c.search.points_2016[k].y) return k + 1;
  return -1;
}
}  // namespace

// From a reset (the ball never seen: the era's estimate is the field centre)
// the first point is the one nearest (0, 0): point 3 (0, 1000) (tied with 7,
// the earlier wins); then table order, round again.
TEST(FindBall2016Era, FromAResetStartsNearestTheCentreThenGoesRoundInOrder) {
  const BehaviourConfig c = config(BehaviourKind::FINDBALL_2016);
  ASSERT_EQ(c.search2016.style, Search2016Style::ERA);  // the default
  EXPECT_EQ(FindBall2016::startIndex(c.search.points_2016, {0, 0}), 2);
  kin::World w;
  w.ball = {20000, 20000};  // never seen
  w.add(2, kRobot2, c);
  std::vector<int> visited;
  while (w.time < 300.0 && visited.size() < 9) {
    w.step();
    const int n = pointNumber(c, w.robots[0].behaviour->searchPoint());
    if (n > 0 && (visited.empty() || visited.back() != n)) visited.push_back(n);
  }
  EXPECT_EQ(visited, (std::vector<int>{3, 4, 5, 6, 7, 8, 1, 2, 3}));
}

// Era style walks through the points: the walk is never stopped (every tick
// a WALK command), the target moves on when the robot is within
// pass_distance of the point (tolerance: one tick of walking, 300 mm/s x
// 1/30 s = 10 mm, plus 5 mm), and the robot passes each point closer than
// pass_distance + 15 mm but never stands there. The earlier style
// (stop_scan_spin) stands at its points: it has STAND ticks.
TEST(FindBall2016Era, WalksThroughThePointsWithoutStopping) {
  const BehaviourConfig c = config(BehaviourKind::FINDBALL_2016);
  kin::World w;
  w.ball = {20000, 20000};
  w.add(2, kRobot2, c);
  int last = -1, switches = 0, stands = 0;
  while (w.time < 120.0) {
    const Pose2 before = w.robots[0].pose;
    w.step();
    if (w.robots[0].last.request.body.type != ActionType::WALK) ++stands;
    const int n = pointNumber(c, w.robots[0].behaviour->searchPoint());
    if (last > 0 && n != last) {
      ++switches;
      const double d = distance(position(before), c.search.points_2016[last - 1]);
      EXPECT_LE(d, c.search2016.pass_distance + 15.0) << "left point " << last << " at " << d << " mm";
    }
    last = n;
  }
  EXPECT_EQ(stands, 0);
  EXPECT_GE(switches, 5);  // 120 s at up to 300 mm/s: several points passed

  BehaviourConfig old = c;
  old.search2016.style = Search2016Style::STOP_SCAN_SPIN;
  kin::World v;
  v.ball = {20000, 20000};
  v.add(2, kRobot2, old);
  int old_stands = 0;
  while (v.time < 120.0) {
    v.step();
    if (v.robots[0].last.request.body.type == ActionType::STAND) ++old_stands;
  }
  EXPECT_GT(old_stands, 30);  // the scans at its points (2.5 s each at 30 Hz)
}

// By default (head: scan) the head sweeps while the robot walks its route:
// over 3 s (30 Hz ticks) the commanded yaw reaches both sides, at least
// 0.5 rad each way (the sweep's limit is +-1.04 rad at 1.68 rad/s).
TEST(FindBall2016Era, HeadSweepsByDefault) {
  const BehaviourConfig c = config(BehaviourKind::FINDBALL_2016);
  Behaviour b(c);
  BehaviourInputs in;
  in.self.pose = {-3000, 2000, 0.3};
  double lo = 0, hi = 0;
  for (int k = 0; k < 90; ++k) {
    in.time = k / 30.0;
    const BehaviourOutput o = b.tick(in);
    lo = std::min<double>(lo, o.request.head.yaw);
    hi = std::max<double>(hi, o.request.head.yaw);
  }
  EXPECT_LT(lo, -0.5);
  EXPECT_GT(hi, 0.5);
}

// head: ball_estimate, the era's head skill with the ball lost, looks at the
// ball estimate: the field centre when never seen. Yaw within 1e-3 rad of the
// bearing, far pitch (0) beyond 880 mm, the head skill's yaw speed.
TEST(FindBall2016Era, HeadLooksAtTheBallEstimate) {
  BehaviourConfig c = config(BehaviourKind::FINDBALL_2016);
  c.search2016.head = Search2016Head::BALL_ESTIMATE;
  Behaviour b(c);
  BehaviourInputs in;
  in.time = 0;
  in.self.pose = {-3000, 2000, 0.3};
  const BehaviourOutput o = b.tick(in);
  const Point2 rel = toRobotFrame(in.self.pose, {0, 0});
  EXPECT_NEAR(o.request.head.yaw, std::atan2(rel.y, rel.x), 1e-3);
  EXPECT_NEAR(o.request.head.pitch, c.search2016.head_far_pitch, 1e-6);
  EXPECT_NEAR(o.request.head.yaw_speed, c.search2016.head_yaw_speed, 1e-5);
}

// The 2017 stop: the spin completes the circle the scan began,
// 2 pi - scan_yaw - camera_hfov (4.18 rad with the defaults); an explicit
// spin_angle wins.
TEST(SearchStop2017, SpinCompletesTheCircleTheScanBegan) {
  SkillConfig s;
  // Outside a program, the V5's lens (60.9 deg).
  EXPECT_NEAR(Spin(s).angle(), 2 * kPi - 1.04 - 60.9 * kPi / 180, 1e-9);
  s.spin_angle = 2 * kPi;
  EXPECT_NEAR(Spin(s).angle(), 2 * kPi, 1e-12);
  // A robot spinning at 0.8 rad/s stops after angle() of turn (+- one tick).
  SkillConfig d;
  Spin spin(d);
  BehaviourInputs in;
  spin.start(in.self.pose);
  double t = 0;
  while (t < 20) {
    const Spin::Output o = spin.tick(in);
    if (o.done) break;
    in.self.pose.theta = wrapAngle(in.self.pose.theta + o.body.turn / 30.0);
    t += 1.0 / 30;
  }
  EXPECT_NEAR(spin.turned(), Spin(d).angle(), 0.8 / 30 + 1e-9);
}

// One searcher per segment: a teammate nearer segment 4's centre that has
// chosen it leaves it worth 0 here; a farther one only divides (the
// thesis's formula); without exclusive_segments it divides in both cases.
TEST(DistributedChoice, ASegmentANearerTeammateChoseIsLeftToIt) {
  StrategyConfig sc;
  const PositionalDistribution d(3, 3);
  auto make = [&](bool exclusive) {
    StrategyConfig s = sc;
    s.exclusive_segments = exclusive;
    return DistributedUtilityCalculator(std::make_unique<SimpleUtilityCalculator>(s), s);
  };
  BehaviourInputs in;
  in.player = 3;
  in.self.pose = {-3000, 0, 0};
  Teammate t;
  t.player = 2;
  t.time_since_heard = 0.1;
  SearchPayload p;
  p.columns = 3;
  p.rows = 3;
  p.segment = 4;  // the centre segment
  t.search = p;
  const double local = SimpleUtilityCalculator(sc).utility(d, 4, in);
  ASSERT_GT(local, 0);
  t.pose = {-500, 0, 0};  // nearer the centre than this robot
  in.teammates = {t};
  EXPECT_EQ(make(true).utility(d, 4, in), 0.0);
  EXPECT_DOUBLE_EQ(make(false).utility(d, 4, in), local / 2);
  t.pose = {-4000, 0, 0};  // farther: this robot keeps its claim
  in.teammates = {t};
  EXPECT_DOUBLE_EQ(make(true).utility(d, 4, in), local / 2);
}

// Keep-out: a teammate 400 mm straight ahead, the target beyond it: the
// walk command has no forward part (nothing closing on it, tolerance
// 1 mm/s). A target a nearer teammate stands on counts as reached from
// 500 mm.
TEST(WalkToKeepOut, NeverClosesOnATeammateAndStopsBesideATakenTarget) {
  const SkillConfig s;
  const WalkTo walk(s, FieldGeometry{});
  BehaviourInputs in;
  in.self.pose = {0, 0, 0};
  Teammate t;
  t.player = 3;
  t.time_since_heard = 0.1;
  t.pose = {400, 0, 0};
  in.teammates = {t};
  const WalkToResult far = walk.tick(in, {3000, 0}, std::nullopt, 300);
  EXPECT_FALSE(far.arrived);
  EXPECT_LE(far.body.forward, 1.0f);
  t.pose = {0, 500, 0};  // beside, standing on the target (0, 600)
  in.teammates = {t};
  EXPECT_TRUE(walk.tick(in, {0, 600}, std::nullopt, 300).arrived);
  in.teammates.clear();
  EXPECT_FALSE(walk.tick(in, {0, 600}, std::nullopt, 300).arrived);
}

// The era's sonar rule (SkillConfig::sonar_*): a side counts after 3 + 1
// near frames from rest, holds 10 frames after the last, and a far echo
// never counts.
TEST(SonarFilter, CountsASideAfterNearFramesAndHoldsIt) {
  const SkillConfig s;
  SonarFilter f(s);
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(f.update(2550, 600).near_right);  // rests at -3
  EXPECT_FALSE(f.update(2550, 300).near_right);  // -2
  EXPECT_FALSE(f.update(2550, 300).near_right);  // -1
  EXPECT_FALSE(f.update(2550, 300).near_right);  // 0
  SonarState st = f.update(2550, 300);           // to the top, 10
  EXPECT_TRUE(st.near_right);
  EXPECT_FALSE(st.near_left);
  for (int i = 0; i < 9; ++i) EXPECT_TRUE(f.update(2550, 2550).near_right) << i;
  EXPECT_FALSE(f.update(2550, 2550).near_right);
}

// A robot the packets do not place there (a teammate whose localisation took
// the mirror twin) but the sonars hear close ahead: the walk does not close
// on it, steps back, and arrives beside it once clear.
TEST(WalkToSonar, NeverClosesOnWhatTheSonarsHearAndStepsBack) {
  const SkillConfig s;
  const WalkTo walk(s, FieldGeometry{});
  BehaviourInputs in;
  in.self.pose = {0, 0, 0};
  const WalkToResult free_walk = walk.tick(in, {3000, 0}, std::nullopt, 300);
  EXPECT_GT(free_walk.body.forward, 100.0f);
  in.sonar.left = in.sonar.right = 300;
  in.sonar.near_left = in.sonar.near_right = true;
  const WalkToResult blocked = walk.tick(in, {3000, 0}, std::nullopt, 300);
  EXPECT_FALSE(blocked.arrived);
  EXPECT_LT(blocked.body.forward, 0.0f);  // backs off
  EXPECT_NEAR(blocked.body.turn, 0.0f, 1e-6);
  // Target 700 mm ahead, an echo at 400 mm but no longer near: reached.
  in.sonar.near_left = in.sonar.near_right = false;
  in.sonar.left = in.sonar.right = 400;
  EXPECT_TRUE(walk.tick(in, {700, 0}, std::nullopt, 300).arrived);
  // Near: steps back first.
  in.sonar.near_left = true;
  EXPECT_FALSE(walk.tick(in, {700, 0}, std::nullopt, 300).arrived);
  // Switched off: the sonars are ignored.
  SkillConfig off = s;
  off.sonar_avoid = false;
  const WalkTo blind(off, FieldGeometry{});
  EXPECT_GT(blind.tick(in, {3000, 0}, std::nullopt, 300).body.forward, 100.0f);
}

// Seeded random starts (fixed here: seeds 1-4), three teammates searching
// 90 s with the ball out of sight: their centres never come closer than
// 2 x 150 mm (touching) -- 2017 and the 2016 era route (where all three
// share the route). Kinematic: exact poses, packets at 5 Hz.
TEST(TeammatesKeepApart, RandomStartsNeverTouch) {
  for (BehaviourKind kind : {BehaviourKind::FINDBALL_2017, BehaviourKind::FINDBALL_2016})
    for (unsigned seed = 1; seed <= 4; ++seed) {
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> x(-4300, 4300), y(-2800, 2800), th(-kPi, kPi);
      kin::World w;
      w.ball = {20000, 20000};
      std::vector<Pose2> starts;
      while (starts.size() < 3) {
        const Pose2 p{x(rng), y(rng), th(rng)};
        bool ok = true;
        for (const Pose2& q : starts) ok = ok && distance(position(p), position(q)) >= 800;
        if (ok) starts.push_back(p);
      }
      for (int i = 0; i < 3; ++i) w.add(2 + i, starts[i], config(kind));
      double closest = 1e9;
      while (w.time < 90.0) {
        w.step();
        for (int i = 0; i < 3; ++i)
          for (int j = i + 1; j < 3; ++j)
            closest = std::min(closest, distance(position(w.robots[i].pose), position(w.robots[j].pose)));
      }
      EXPECT_GT(closest, 300.0) << behaviourKindName(kind) << " seed " << seed;
    }
}
