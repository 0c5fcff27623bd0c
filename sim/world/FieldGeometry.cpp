// The field's static collision geometry: the carpet (an infinite plane at
// z = 0; the carpet's 10.4 x 7.4 m extent only matters to rendering), and at
// each end a goal (two posts and a crossbar, as capsules) with a net made of
// thin boxes (back, two sides, top) that stops the ball.
//
// Capsules rather than ODE cylinders: ODE 0.16 without libccd cannot
// collide cylinders with capsules, and robot links may be capsules.
#include "sim/world/WorldImpl.hpp"

namespace simswift {

namespace {
constexpr double kNetThickness = 0.02;  // m: thick enough that a 3 m/s ball cannot tunnel in 5 ms
}

void World::Impl::buildField(const FieldConfig& field) {
  auto tag = [&](dGeomID g, GeomTag::Kind kind) {
    static_tags.push_back(std::make_unique<GeomTag>(GeomTag{kind, -1, -1}));
    dGeomSetData(g, static_tags.back().get());
  };

  dGeomID ground = dCreatePlane(static_space, 0, 0, 1, 0);
  tag(ground, GeomTag::Ground);

  const GoalConfig& g = field.goal;
  const double r = g.post_diameter / 2;
  const double post_y = g.inner_width / 2 + r;           // post centre |y| (0.8 m)
  const double bar_z = g.post_height - r;                // crossbar axis height
  const double t = kNetThickness;
  for (double s : {-1.0, 1.0}) {
    const double gx = s * field.length / 2;              // goal line centre x
    // Posts: vertical capsules, axis from z = 0 to the crossbar axis (the
    // bottom cap sinks into the ground, which is harmless for static geoms).
    for (double side : {-1.0, 1.0}) {
      dGeomID post = dCreateCapsule(static_space, r, bar_z);
      dGeomSetPosition(post, gx, side * post_y, bar_z / 2);
      tag(post, GeomTag::FieldObject);
    }
    // Crossbar: a capsule along y between the post centres.
    dGeomID bar = dCreateCapsule(static_space, r, 2 * post_y);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, M_PI / 2);  // local z -> world y
    dGeomSetRotation(bar, R);
    dGeomSetPosition(bar, gx, 0, bar_z);
    tag(bar, GeomTag::FieldObject);

    // Net: the back just behind `depth`, sides flush with the posts' inner
    // faces, the top at net_height; every face reaches the ground.
    const double back_x = s * (field.length / 2 + g.depth + t / 2);
    const double mid_x = s * (field.length / 2 + g.depth / 2);
    dGeomID back = dCreateBox(static_space, t, g.inner_width + 2 * t, g.net_height);
    dGeomSetPosition(back, back_x, 0, g.net_height / 2);
    tag(back, GeomTag::Net);
    for (double side : {-1.0, 1.0}) {
      dGeomID wall = dCreateBox(static_space, g.depth, t, g.net_height);
      dGeomSetPosition(wall, mid_x, side * (g.inner_width / 2 + t / 2), g.net_height / 2);
      tag(wall, GeomTag::Net);
    }
    dGeomID top = dCreateBox(static_space, g.depth, g.inner_width + 2 * t, t);
    dGeomSetPosition(top, mid_x, 0, g.net_height + t / 2);
    tag(top, GeomTag::Net);
  }
}

}  // namespace simswift
