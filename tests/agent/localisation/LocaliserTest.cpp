// Localisation on a synthetic field (tests/agent/localisation/SyntheticField.hpp):
// convergence from a wrong start, a teleport detected as a flip, the
// symmetric pose rejected. Each claim holds over 10 seeds (1..10; the filter
// was tuned on seeds 1001..1020, never these).
#include <gtest/gtest.h>

#include <cmath>

#include "agent/localisation/Localiser.hpp"
#include "tests/agent/localisation/SyntheticField.hpp"

namespace bb = agent::blackboard;
namespace localisation = agent::localisation;
using loc_test::headingError;
using loc_test::poseError;
using loc_test::SyntheticRobot;

namespace {
constexpr double kDt = 1.0 / 30;  // s per frame
constexpr double kDeg = M_PI / 180;

// Walks forward 200 mm/s while turning 0.15 rad/s, feeding the filter.
struct Walk {
  SyntheticRobot robot;
  localisation::Localiser loc;
  double t = 0;
  Walk(uint64_t seed, bb::FieldPose start) : robot(seed, start), loc(config(seed)) {}
  static localisation::LocaliserConfig config(uint64_t seed) {
    localisation::LocaliserConfig c;
    c.seed = seed * 7919 + 1;
    return c;
  }
  void frames(int n, double forward = 200, double turn = 0.15) {
    for (int i = 0; i < n; ++i) {
      double f, l, r;
      robot.walk(forward, 0, turn, kDt, &f, &l, &r);
      t += kDt;
      loc.update(f, l, r, robot.see(t), t);
    }
  }
};
}  // namespace

TEST(Localiser, ConvergesFromAWrongStartWithin10sOfWalkingPastFeatures) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Walk w(seed, {-2500, -1000, 0.3});
    // The belief starts 2 m and 50 degrees away, and sure of itself.
    w.loc.resetTo({-1000, 500, -0.6}, 100, 0.1);
    ASSERT_GT(poseError(w.loc.estimate().pose, w.robot.truth()), 1500);
    w.frames(300);  // 10 s
    const bb::FieldPose e = w.loc.estimate().pose;
    EXPECT_LT(poseError(e, w.robot.truth()), 300) << "seed " << seed;
    EXPECT_LT(headingError(e, w.robot.truth()), 15 * kDeg) << "seed " << seed;
  }
}

TEST(Localiser, TracksWithinToleranceWhileWalking) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Walk w(seed, {-3000, 1500, -0.5});
    w.loc.resetTo(w.robot.truth(), 50, 0.05);
    double worst = 0;
    for (int k = 0; k < 20; ++k) {  // 20 s, checked every second
      w.frames(30);
      worst = std::max(worst, poseError(w.loc.estimate().pose, w.robot.truth()));
      EXPECT_LT(headingError(w.loc.estimate().pose, w.robot.truth()), 15 * kDeg) << "seed " << seed;
    }
    EXPECT_LT(worst, 300) << "seed " << seed;
    EXPECT_EQ(w.loc.estimate().jumps, 0) << "seed " << seed;
  }
}

TEST(Localiser, TeleportIsDetectedAsAFlipWithin3s) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Walk w(seed, {-3000, -500, 0.2});
    w.loc.resetTo(w.robot.truth(), 50, 0.05);
    w.frames(90);
    ASSERT_LT(poseError(w.loc.estimate().pose, w.robot.truth()), 300) << "seed " << seed;
    const int jumps_before = w.loc.estimate().jumps;
    // Carried 1.8 m away and turned by 70 degrees; odometry knows nothing.
    const bb::FieldPose p = w.robot.truth();
    w.robot.teleport({p.x + 1200, p.y + 1300, p.theta + 70 * kDeg});
    const double t0 = w.t;
    double flagged = -1;
    for (int i = 0; i < 90 && flagged < 0; ++i) {
      w.frames(1);
      if (w.loc.estimate().jumped) flagged = w.t - t0;
    }
    EXPECT_GE(flagged, 0) << "seed " << seed << ": no flip within 3 s";
    EXPECT_GT(w.loc.estimate().jumps, jumps_before);
    EXPECT_GT(w.loc.estimate().jump_time, t0);
    // One frame can fit an alias as well as the truth (two anonymous corners
    // and a line); walking on, the truth wins within 10 s.
    w.frames(int(std::lround((10.0 - (w.t - t0)) / kDt)));
    EXPECT_LT(poseError(w.loc.estimate().pose, w.robot.truth()), 300) << "seed " << seed;
    EXPECT_LT(headingError(w.loc.estimate().pose, w.robot.truth()), 15 * kDeg) << "seed " << seed;
  }
}

TEST(Localiser, SymmetricPoseIsRejected) {
  // The field is point-symmetric: the mirror pose explains a frame exactly as
  // well as the true one...
  SyntheticRobot probe(99, {-2000, 2800, -M_PI / 2});
  localisation::Localiser l;
  const bb::VisionMeasurements v = probe.see(0);
  const bb::FieldPose t = probe.truth();
  localisation::Particle truth{t.x, t.y, t.theta, 1}, mirror{-t.x, -t.y, localisation::wrapAngle(t.theta + M_PI), 1};
  ASSERT_GT(v.num_features, 3);
  EXPECT_NEAR(l.frameLikelihood(truth, v), l.frameLikelihood(mirror, v), 1e-9);
  // ...so only the starting side tells them apart. Entering from the
  // touch line of the own half (the game state's initial pose), the estimate
  // must settle on the true pose, never the mirror.
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Walk w(seed, {-2000 + 150.0 * (seed % 10), (seed % 2 ? 2950.0 : -2950.0), (seed % 2 ? -M_PI / 2 : M_PI / 2)});
    w.loc.reset(localisation::InitialPose::SidelineEntry);
    int mirror_frames = 0;
    for (int i = 0; i < 300; ++i) {
      w.frames(1, 180, 0.1);
      const bb::FieldPose e = w.loc.estimate().pose;
      const bb::FieldPose tr = w.robot.truth();
      const bb::FieldPose mi{-tr.x, -tr.y, tr.theta + M_PI};
      if (poseError(e, mi) < poseError(e, tr)) ++mirror_frames;
    }
    EXPECT_EQ(mirror_frames, 0) << "seed " << seed;
    EXPECT_LT(poseError(w.loc.estimate().pose, w.robot.truth()), 300) << "seed " << seed;
    EXPECT_LT(headingError(w.loc.estimate().pose, w.robot.truth()), 15 * kDeg) << "seed " << seed;
  }
}

// The bound's bookkeeping; its effect in physics: tests/behaviour_physics/
// test_halfway_entry.cpp (the synthetic detector here sees too much of the
// field for the twins to be confused near the halfway line).
TEST(Localiser, OwnHalfBoundGrowsWithTheDistanceWalked) {
  const localisation::LocaliserConfig c;
  localisation::Localiser l(c);
  l.reset(localisation::InitialPose::SidelineEntry);
  EXPECT_DOUBLE_EQ(l.ownHalfBound(), c.entry_x_max + c.bound_margin);
  const bb::VisionMeasurements none{};
  for (int i = 0; i < 10; ++i) l.update(60, 80, 0, none, i / 30.0);  // 100 mm per frame
  EXPECT_NEAR(l.ownHalfBound(), c.entry_x_max + c.bound_margin + c.bound_walk_factor * 1000, 1e-6);
  l.reset(localisation::InitialPose::PenaltyReturn);
  EXPECT_LT(l.ownHalfBound(), -1000);  // back at the own penalty mark's x
  for (int i = 0; i < 70; ++i) l.update(100, 0, 0, none, i / 30.0);  // 7 m: anywhere on the field now
  EXPECT_EQ(l.ownHalfBound(), localisation::Localiser::kNoBound);
  l.resetTo({2000, 0, 0});  // a known start: the team placed it, anywhere
  EXPECT_EQ(l.ownHalfBound(), localisation::Localiser::kNoBound);
  localisation::LocaliserConfig off;
  off.own_half_bound = false;
  localisation::Localiser u(off);
  u.reset(localisation::InitialPose::SidelineEntry);
  EXPECT_EQ(u.ownHalfBound(), localisation::Localiser::kNoBound);
}

TEST(Localiser, SameSeedSameEstimate) {
  Walk a(3, {-2000, 0, 0}), b(3, {-2000, 0, 0});
  a.loc.reset(localisation::InitialPose::OwnHalf);
  b.loc.reset(localisation::InitialPose::OwnHalf);
  a.frames(60);
  b.frames(60);
  EXPECT_EQ(a.loc.estimate().pose.x, b.loc.estimate().pose.x);
  EXPECT_EQ(a.loc.estimate().pose.theta, b.loc.estimate().pose.theta);
}

TEST(FieldModel, LandmarksAreThePointSymmetricSpl2017Set) {
  const localisation::FieldModel f = localisation::FieldModel::spl2017();
  const auto lm = f.landmarks();
  int posts = 0, corners = 0;
  for (const localisation::Landmark& l : lm) {
    posts += l.kind == bb::FeatureKind::GoalPost;
    corners += l.kind == bb::FeatureKind::Corner;
    // Every landmark has its mirror twin of the same kind.
    bool twin = false;
    for (const localisation::Landmark& m : lm)
      twin |= m.kind == l.kind && std::fabs(m.at.x + l.at.x) < 1e-9 && std::fabs(m.at.y + l.at.y) < 1e-9;
    EXPECT_TRUE(twin) << l.at.x << ", " << l.at.y;
  }
  EXPECT_EQ(posts, 4);
  EXPECT_EQ(corners, 16);  // 8 L, 6 T, 2 X
  EXPECT_NEAR(localisation::distanceToLines({0, 750}, f.lines(), 750), 0, 1e-9);
  EXPECT_NEAR(localisation::distanceToLines({-3900, 0}, f.lines(), 750), 0, 1e-9);
  EXPECT_NEAR(localisation::distanceToLines({-2000, 2000}, f.lines(), 750), 1000, 1e-9);
}

TEST(FieldModel, PreparedLinesGiveExactlyTheReferenceDistance) {
  // The filter's prepared lines (skipping segments that cannot be nearer)
  // must give bit for bit what the plain scan gives, so the filter's output
  // does not change: points on a 10 mm grid over the field and beyond, plus
  // a slanted segment (none on the SPL field) to cover the general case.
  const localisation::FieldModel f = localisation::FieldModel::spl2017();
  std::vector<localisation::LineSegment> lines = f.lines();
  const localisation::FieldLines spl(lines, f.centre_circle_radius);
  lines.push_back({{-1000, -500}, {2000, 1700}});
  const localisation::FieldLines with_slant(lines, f.centre_circle_radius);
  const std::vector<localisation::LineSegment> spl_lines = f.lines();
  int checked = 0;
  for (double x = -5600; x <= 5600; x += 10)
    for (double y = -3700; y <= 3700; y += 10) {
      const localisation::Vec2 p{x + 0.37, y - 0.21};
      ASSERT_EQ(spl.distance(p), localisation::distanceToLines(p, spl_lines, f.centre_circle_radius)) << x << ", " << y;
      ASSERT_EQ(with_slant.distance(p), localisation::distanceToLines(p, lines, f.centre_circle_radius))
          << x << ", " << y;
      ++checked;
    }
  EXPECT_GT(checked, 800000);
}
