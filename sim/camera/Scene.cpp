#include "sim/camera/Scene.hpp"

#include <GL/gl.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace simswift::camera {

namespace {

constexpr int kBallSlices = 48, kBallStacks = 32;       // the ball: finer, its outline is measured
constexpr int kCylinderSlices = 48;
constexpr int kCircleSegments = 128;                    // centre circle band
constexpr double kBallPatchAngle = 0.40;                // rad: black patch radius on the unit sphere

void vertex(const Eigen::Vector3d& p) { glVertex3d(p.x(), p.y(), p.z()); }
void normal(const Eigen::Vector3d& n) { glNormal3d(n.x(), n.y(), n.z()); }
void colour(const Eigen::Vector3f& c, float a = 1.0f) { glColor4f(c.x(), c.y(), c.z(), a); }

Eigen::Vector3d spherePoint(int slice, int stack, int slices, int stacks) {
  const double phi = 2 * M_PI * slice / slices;        // azimuth
  const double theta = M_PI * stack / stacks;          // from +z down
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Unit sphere (radius 1) as triangles. With `patches`, each triangle is black
// if its centre lies within kBallPatchAngle of one of the 12 icosahedron
// vertices (the pentagons of a football), otherwise white.
void emitSphere(int slices, int stacks, bool patches) {
  static const double g = (1 + std::sqrt(5.0)) / 2;
  static const Eigen::Vector3d kIco[12] = {
      {0, 1, g}, {0, -1, g}, {0, 1, -g}, {0, -1, -g}, {1, g, 0}, {-1, g, 0},
      {1, -g, 0}, {-1, -g, 0}, {g, 0, 1}, {-g, 0, 1}, {g, 0, -1}, {-g, 0, -1}};
  const double cos_patch = std::cos(kBallPatchAngle);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const Eigen::Vector3d a = spherePoint(j, i, slices, stacks);
      const Eigen::Vector3d b = spherePoint(j, i + 1, slices, stacks);
      const Eigen::Vector3d c = spherePoint(j + 1, i + 1, slices, stacks);
      const Eigen::Vector3d d = spherePoint(j + 1, i, slices, stacks);
      for (const auto& tri : {std::array<Eigen::Vector3d, 3>{a, b, c}, std::array<Eigen::Vector3d, 3>{a, c, d}}) {
        if ((tri[0] - tri[1]).norm() < 1e-12 || (tri[1] - tri[2]).norm() < 1e-12 ||
            (tri[0] - tri[2]).norm() < 1e-12)
          continue;  // degenerate at the poles
        if (patches) {
          const Eigen::Vector3d centre = (tri[0] + tri[1] + tri[2]).normalized();
          bool black = false;
          for (const auto& v : kIco) black = black || centre.dot(v.normalized()) > cos_patch;
          const float k = black ? 0.05f : 0.95f;
          glColor3f(k, k, k);
        }
        for (const auto& p : tri) {
          normal(p);
          vertex(p);
        }
      }
    }
  }
  glEnd();
}

// Unit cylinder: radius 1, axis z from -0.5 to 0.5, with caps.
void emitCylinder(int slices) {
  glBegin(GL_QUAD_STRIP);
  for (int j = 0; j <= slices; ++j) {
    const double phi = 2 * M_PI * j / slices;
    const double c = std::cos(phi), s = std::sin(phi);
    glNormal3d(c, s, 0);
    glVertex3d(c, s, 0.5);
    glVertex3d(c, s, -0.5);
  }
  glEnd();
  for (double z : {0.5, -0.5}) {
    glBegin(GL_TRIANGLE_FAN);
    glNormal3d(0, 0, z > 0 ? 1 : -1);
    glVertex3d(0, 0, z);
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2 * M_PI * (z > 0 ? j : slices - j) / slices;
      glVertex3d(std::cos(phi), std::sin(phi), z);
    }
    glEnd();
  }
}

// Unit cube centred at the origin (side 1).
void emitCube() {
  static const double n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  glBegin(GL_QUADS);
  for (const auto& f : n) {
    const Eigen::Vector3d nn(f[0], f[1], f[2]);
    // Two unit vectors spanning the face, ordered so the quad winds CCW seen from outside.
    const Eigen::Vector3d u = std::abs(nn.z()) > 0.5 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
    const Eigen::Vector3d v = nn.cross(u);
    normal(nn);
    vertex(0.5 * (nn - u - v));
    vertex(0.5 * (nn + u - v));
    vertex(0.5 * (nn + u + v));
    vertex(0.5 * (nn - u + v));
  }
  glEnd();
}

// A flat quad on the ground (z = 0) from a to b (m), `width` wide.
void groundStrip(double ax, double ay, double bx, double by, double width) {
  Eigen::Vector2d d(bx - ax, by - ay);
  const double len = d.norm();
  if (len < 1e-9) return;
  d /= len;
  const Eigen::Vector2d n(-d.y() * width / 2, d.x() * width / 2);
  // Extend along the line by half a width so corners close like painted lines.
  const Eigen::Vector2d a = Eigen::Vector2d(ax, ay) - d * width / 2, b = Eigen::Vector2d(bx, by) + d * width / 2;
  glVertex3d(a.x() - n.x(), a.y() - n.y(), 0);
  glVertex3d(b.x() - n.x(), b.y() - n.y(), 0);
  glVertex3d(b.x() + n.x(), b.y() + n.y(), 0);
  glVertex3d(a.x() + n.x(), a.y() + n.y(), 0);
}

void multMatrix(const Eigen::Isometry3d& t) {
  const Eigen::Matrix4d m = t.matrix();  // column-major, as OpenGL expects
  glMultMatrixd(m.data());
}

// A cylinder of radius r from p to q (m).
void cylinderBetween(GLuint list, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double r) {
  const Eigen::Vector3d axis = q - p;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = (p + q) / 2;
  t.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis.normalized()).toRotationMatrix();
  glPushMatrix();
  multMatrix(t);
  glScaled(r, r, axis.norm());
  glCallList(list);
  glPopMatrix();
}

std::string stripPrefix(std::string p) {
  const std::string file = "file://", pkg = "package://";
  if (p.compare(0, file.size(), file) == 0) return p.substr(file.size());
  if (p.compare(0, pkg.size(), pkg) == 0) {
    p = p.substr(pkg.size());
    const auto slash = p.find('/');
    return slash == std::string::npos ? p : p.substr(slash + 1);
  }
  return p;
}

bool fileExists(const std::string& p) {
  std::ifstream f(p);
  return f.good();
}

}  // namespace

// Triangles of one mesh file, in the file's own frame and units (m).
struct Scene::MeshData {
  std::vector<Eigen::Vector3f> positions;  // 3 per triangle
  std::vector<Eigen::Vector3f> normals;
};

// GL state owned by the Scene for one context.
struct Scene::Gl {
  uint64_t context_id = 0;
  GLuint base = 0;  // glGenLists base
  GLuint ground = 0, cube = 0, sphere = 0, cylinder = 0, ball = 0, goals = 0, net = 0;
};

Scene::Scene(const FieldConfig& field, SceneOptions options) : field_(field), options_(std::move(options)) {
  if (options_.team_colours.empty()) throw std::invalid_argument("SceneOptions: team_colours is empty");
}


Eigen::Vector2d Scene::goalPostCentre(const FieldConfig& field, int goal, int post) {
  const double r = field.goal.post_diameter / 2;
  return {(goal == 0 ? -1 : 1) * field.length / 2, (post == 0 ? -1 : 1) * (field.goal.inner_width / 2 + r)};
}

const Scene::MeshData& Scene::mesh(const std::string& path, const std::string& link) const {
  for (const auto& m : meshes_)
    if (m.first == path) return *m.second;
  const std::string rel = stripPrefix(path);
  std::string found;
  if (fileExists(rel)) found = rel;
  for (size_t i = 0; found.empty() && i < options_.mesh_dirs.size(); ++i) {
    const std::string p = options_.mesh_dirs[i] + "/" + rel;
    if (fileExists(p)) found = p;
  }
  if (found.empty())
    throw std::runtime_error("link '" + link + "': mesh '" + path + "' not found (searched as given and in " +
                             std::to_string(options_.mesh_dirs.size()) + " mesh folder(s))");
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(found, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                   aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (!s || !s->mRootNode)
    throw std::runtime_error("link '" + link + "': mesh '" + found + "': " + importer.GetErrorString());
  auto data = std::make_unique<MeshData>();
  for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
    const aiMesh* m = s->mMeshes[mi];
    for (unsigned fi = 0; fi < m->mNumFaces; ++fi) {
      const aiFace& f = m->mFaces[fi];
      if (f.mNumIndices != 3) continue;  // points and lines are not drawn
      for (int k = 0; k < 3; ++k) {
        const aiVector3D& v = m->mVertices[f.mIndices[k]];
        const aiVector3D& n = m->mNormals[f.mIndices[k]];
        data->positions.emplace_back(v.x, v.y, v.z);
        data->normals.emplace_back(n.x, n.y, n.z);
      }
    }
  }
  if (data->positions.empty())
    throw std::runtime_error("link '" + link + "': mesh '" + found + "' has no triangles");
  meshes_.emplace_back(path, std::move(data));
  return *meshes_.back().second;
}


void Scene::buildLists() const {
  gl_ = std::make_unique<Gl>();
  Gl& g = *gl_;
  g.base = glGenLists(7);
  g.ground = g.base;
  g.cube = g.base + 1;
  g.sphere = g.base + 2;
  g.cylinder = g.base + 3;
  g.ball = g.base + 4;
  g.goals = g.base + 5;
  g.net = g.base + 6;

  glNewList(g.cube, GL_COMPILE);
  emitCube();
  glEndList();
  glNewList(g.cylinder, GL_COMPILE);
  emitCylinder(kCylinderSlices);
  glEndList();
  glNewList(g.ball, GL_COMPILE);
  emitSphere(kBallSlices, kBallStacks, true);
  glEndList();

  // Carpet and painted lines: unlit, flat colours, drawn first with no depth
  // test (everything else stands on them).
  const FieldConfig& f = field_;
  glNewList(g.ground, GL_COMPILE);
  colour(options_.carpet);
  glNormal3d(0, 0, 1);
  glBegin(GL_QUADS);
  const double hx = f.carpetLength() / 2, hy = f.carpetWidth() / 2;
  glVertex3d(-hx, -hy, 0);
  glVertex3d(hx, -hy, 0);
  glVertex3d(hx, hy, 0);
  glVertex3d(-hx, hy, 0);
  colour(options_.lines);
  for (const auto& l : f.lines) groundStrip(l.ax, l.ay, l.bx, l.by, l.width);
  for (const auto& c : f.crosses) {
    groundStrip(c.x - c.size / 2 + c.width / 2, c.y, c.x + c.size / 2 - c.width / 2, c.y, c.width);
    groundStrip(c.x, c.y - c.size / 2 + c.width / 2, c.x, c.y + c.size / 2 - c.width / 2, c.width);
  }
  glEnd();
  for (const auto& c : f.circles) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= kCircleSegments; ++i) {
      const double a = 2 * M_PI * i / kCircleSegments;
      const double ri = c.radius - c.width / 2, ro = c.radius + c.width / 2;
      glVertex3d(c.cx + ro * std::cos(a), c.cy + ro * std::sin(a), 0);
      glVertex3d(c.cx + ri * std::cos(a), c.cy + ri * std::sin(a), 0);
    }
    glEnd();
  }
  glEndList();

  // Goals: white posts (z = 0 .. post_height) and a crossbar whose axis is
  // post_diameter/2 below the top, as in the World's collision geometry.
  const GoalConfig& gc = f.goal;
  const double r = gc.post_diameter / 2;
  glNewList(g.goals, GL_COMPILE);
  glColor3f(0.96f, 0.96f, 0.96f);
  for (int goal = 0; goal < 2; ++goal) {
    for (int post = 0; post < 2; ++post) {
      const Eigen::Vector2d c = goalPostCentre(f, goal, post);
      cylinderBetween(g.cylinder, {c.x(), c.y(), 0}, {c.x(), c.y(), gc.post_height}, r);
    }
    const Eigen::Vector2d a = goalPostCentre(f, goal, 0), b = goalPostCentre(f, goal, 1);
    cylinderBetween(g.cylinder, {a.x(), a.y() - r, gc.post_height - r}, {b.x(), b.y() + r, gc.post_height - r}, r);
  }
  glEndList();

  // Net: a 0.1 m grid of 1-pixel grey lines on the back, sides and top, unlit.
  glNewList(g.net, GL_COMPILE);
  glColor3f(0.80f, 0.80f, 0.80f);
  glBegin(GL_LINES);
  const double step = 0.1;
  for (int goal = 0; goal < 2; ++goal) {
    const double s = goal == 0 ? -1 : 1;
    const double x0 = s * f.length / 2, x1 = s * (f.length / 2 + gc.depth);
    const double y0 = -gc.inner_width / 2, y1 = gc.inner_width / 2, h = gc.net_height;
    auto line = [](double ax, double ay, double az, double bx, double by, double bz) {
      glVertex3d(ax, ay, az);
      glVertex3d(bx, by, bz);
    };
    for (double z = 0; z <= h + 1e-9; z += step) {
      line(x1, y0, z, x1, y1, z);                   // back, horizontal
      line(x0, y0, z, x1, y0, z);                   // sides
      line(x0, y1, z, x1, y1, z);
    }
    for (double y = y0; y <= y1 + 1e-9; y += step) {
      line(x1, y, 0, x1, y, h);                     // back, vertical
      line(x0, y, h, x1, y, h);                     // top, along x
    }
    for (double t = 0; t <= gc.depth + 1e-9; t += step) {
      const double x = x0 + s * t;
      line(x, y0, 0, x, y0, h);                     // sides, vertical
      line(x, y1, 0, x, y1, h);
      line(x, y0, h, x, y1, h);                     // top, along y
    }
  }
  glEnd();
  glEndList();
}

namespace {

// Unit primitives as triangle soups (positions and unit normals), built once.
struct UnitMesh {
  std::vector<Eigen::Vector3f> p, n;
  void add(const Eigen::Vector3d& pos, const Eigen::Vector3d& nrm) {
    p.push_back(pos.cast<float>());
    n.push_back(nrm.normalized().cast<float>());
  }
};

constexpr int kRobotSphereSlices = 20, kRobotSphereStacks = 12, kRobotCylinderSlices = 24;

const UnitMesh& unitSphere() {
  static const UnitMesh m = [] {
    UnitMesh u;
    for (int i = 0; i < kRobotSphereStacks; ++i)
      for (int j = 0; j < kRobotSphereSlices; ++j) {
        const auto a = spherePoint(j, i, kRobotSphereSlices, kRobotSphereStacks);
        const auto b = spherePoint(j, i + 1, kRobotSphereSlices, kRobotSphereStacks);
        const auto c = spherePoint(j + 1, i + 1, kRobotSphereSlices, kRobotSphereStacks);
        const auto d = spherePoint(j + 1, i, kRobotSphereSlices, kRobotSphereStacks);
        if (i != kRobotSphereStacks - 1) u.add(a, a), u.add(b, b), u.add(c, c);
        if (i != 0) u.add(a, a), u.add(c, c), u.add(d, d);
      }
    return u;
  }();
  return m;
}

const UnitMesh& unitCylinder() {  // radius 1, z from -0.5 to 0.5, capped
  static const UnitMesh m = [] {
    UnitMesh u;
    for (int j = 0; j < kRobotCylinderSlices; ++j) {
      const double a0 = 2 * M_PI * j / kRobotCylinderSlices, a1 = 2 * M_PI * (j + 1) / kRobotCylinderSlices;
      const Eigen::Vector3d r0(std::cos(a0), std::sin(a0), 0), r1(std::cos(a1), std::sin(a1), 0);
      const Eigen::Vector3d up(0, 0, 0.5), z(0, 0, 1);
      u.add(r0 - up, r0), u.add(r1 - up, r1), u.add(r1 + up, r1);
      u.add(r0 - up, r0), u.add(r1 + up, r1), u.add(r0 + up, r0);
      u.add(up, z), u.add(r0 + up, z), u.add(r1 + up, z);
      u.add(-up, -z), u.add(r1 - up, -z), u.add(r0 - up, -z);
    }
    return u;
  }();
  return m;
}

const UnitMesh& unitCube() {  // side 1, centred
  static const UnitMesh m = [] {
    UnitMesh u;
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {-1.0, 1.0}) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        n[axis] = sign;
        Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
        a[(axis + 1) % 3] = 1;
        b[(axis + 2) % 3] = 1;
        const Eigen::Vector3d c[4] = {0.5 * (n - a - b), 0.5 * (n + a - b), 0.5 * (n + a + b), 0.5 * (n - a + b)};
        u.add(c[0], n), u.add(c[1], n), u.add(c[2], n);
        u.add(c[0], n), u.add(c[2], n), u.add(c[3], n);
      }
    return u;
  }();
  return m;
}

}  // namespace

// A link's visual triangles in the link frame, with colours.
struct Scene::LinkGeometry {
  std::vector<Eigen::Vector3f> p, n;
  std::vector<Eigen::Vector4f> c;
  void add(const std::vector<Eigen::Vector3f>& pos, const std::vector<Eigen::Vector3f>& nrm,
           const Eigen::Affine3d& t, const Eigen::Vector4f& colour) {
    const Eigen::Matrix3f lin = t.linear().cast<float>();
    const Eigen::Matrix3f nmat = t.linear().inverse().transpose().cast<float>();  // normals under scaling
    const Eigen::Vector3f off = t.translation().cast<float>();
    for (size_t i = 0; i < pos.size(); ++i) {
      p.push_back(lin * pos[i] + off);
      n.push_back((nmat * nrm[i]).normalized());
      c.push_back(colour);
    }
  }
};

const std::vector<Scene::LinkGeometry>& Scene::modelGeometry(const RobotModel& model) const {
  for (const auto& g : geometry_)
    if (g.first == &model) return g.second;
  std::vector<LinkGeometry> links(model.links().size());
  for (size_t li = 0; li < links.size(); ++li) {
    const LinkSpec& link = model.links()[li];
    for (const ShapeSpec& s : link.visuals) {
      const Eigen::Vector4f col = s.rgba.cast<float>();
      const Eigen::Affine3d o(s.origin.isometry().matrix());
      auto scaled = [&](const Eigen::Vector3d& k, const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
        return o * Eigen::Translation3d(shift) * Eigen::Scaling(k);
      };
      switch (s.type) {
        case ShapeType::Box: links[li].add(unitCube().p, unitCube().n, scaled(s.size), col); break;
        case ShapeType::Sphere:
          links[li].add(unitSphere().p, unitSphere().n, scaled(Eigen::Vector3d::Constant(s.radius)), col);
          break;
        case ShapeType::Cylinder:
          links[li].add(unitCylinder().p, unitCylinder().n, scaled({s.radius, s.radius, s.length}), col);
          break;
        case ShapeType::Capsule:
          links[li].add(unitCylinder().p, unitCylinder().n, scaled({s.radius, s.radius, s.length}), col);
          for (double z : {-s.length / 2, s.length / 2})
            links[li].add(unitSphere().p, unitSphere().n, scaled(Eigen::Vector3d::Constant(s.radius), {0, 0, z}), col);
          break;
        case ShapeType::Mesh: {
          const MeshData& m = mesh(s.mesh, link.name);
          links[li].add(m.positions, m.normals, o, col);
          break;
        }
      }
    }
    if (options_.draw_jerseys && static_cast<int>(li) == model.rootLink()) {
      // Jersey: a band around the torso's first box visual (or a NAO-sized
      // default), slightly proud of it so it shows on every side. Its colour
      // is set per robot at draw time (alpha 0 marks it here).
      Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
      Eigen::Vector3d size(0.09, 0.12, 0.16);
      at.translation() = Eigen::Vector3d(-0.008, 0, 0.045);
      for (const auto& v : link.visuals)
        if (v.type == ShapeType::Box) {
          at = v.origin.isometry();
          size = v.size;
          break;
        }
      const Eigen::Affine3d band = Eigen::Affine3d(at.matrix()) * Eigen::Translation3d(0, 0, 0.1 * size.z()) *
                                   Eigen::Scaling(Eigen::Vector3d(size.x() + 0.006, size.y() + 0.006, 0.4 * size.z()));
      links[li].add(unitCube().p, unitCube().n, band, Eigen::Vector4f(0, 0, 0, 0));
    }
  }
  geometry_.emplace_back(&model, std::move(links));
  return geometry_.back().second;
}

void Scene::preloadModel(const RobotModel& model) { modelGeometry(model); }

// All robots in one vertex array, transformed on the CPU: one draw call for
// every robot instead of one per shape (llvmpipe's per-draw cost dominates).
void Scene::drawRobots(const DrawOptions& options) const {
  auto& p = scratch_p_;
  auto& n = scratch_n_;
  auto& c = scratch_c_;
  p.clear(), n.clear(), c.clear();
  const int nteams = static_cast<int>(options_.team_colours.size());
  for (size_t ri = 0; ri < robots.size(); ++ri) {
    const RobotDrawState& robot = robots[ri];
    if (!robot.model) continue;
    const auto& geometry = modelGeometry(*robot.model);
    if (robot.link_poses.size() != geometry.size())
      throw std::invalid_argument("Scene: robot " + std::to_string(ri) + " has " +
                                  std::to_string(robot.link_poses.size()) + " link poses for " +
                                  std::to_string(geometry.size()) + " links");
    const Eigen::Vector3f& jersey = options_.team_colours[((robot.team % nteams) + nteams) % nteams];
    const Eigen::Vector4f jersey4(jersey.x(), jersey.y(), jersey.z(), 1);
    for (size_t li = 0; li < geometry.size(); ++li) {
      if (static_cast<int>(ri) == options.hide_robot && static_cast<int>(li) == options.hide_link) continue;
      const LinkGeometry& g = geometry[li];
      const Eigen::Matrix3f rot = robot.link_poses[li].linear().cast<float>();
      const Eigen::Vector3f off = robot.link_poses[li].translation().cast<float>();
      for (size_t i = 0; i < g.p.size(); ++i) {
        p.push_back(rot * g.p[i] + off);
        n.push_back(rot * g.n[i]);
        c.push_back(g.c[i].w() == 0 ? jersey4 : g.c[i]);
      }
    }
  }
  if (p.empty()) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(Eigen::Vector3f), p.data());
  glNormalPointer(GL_FLOAT, sizeof(Eigen::Vector3f), n.data());
  glColorPointer(4, GL_FLOAT, sizeof(Eigen::Vector4f), c.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(p.size()));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

void Scene::draw(uint64_t context_id, const DrawOptions& options) const {
  if (!gl_ || gl_->context_id != context_id) {
    buildLists();
    gl_->context_id = context_id;
  }
  const Gl& g = *gl_;

  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glCallList(g.ground);

  glEnable(GL_DEPTH_TEST);
  if (options_.draw_net) glCallList(g.net);

  // One directional light from above and to the side, in world coordinates
  // (the modelview holds the view, so the direction is transformed with it).
  glEnable(GL_LIGHTING);
  const GLfloat light_dir[4] = {0.35f, 0.25f, 0.90f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
  glCallList(g.goals);

  if (show_ball) {
    const double r = field_.ball.diameter / 2;
    glPushMatrix();
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = ball_position;
    t.linear() = ball_orientation.normalized().toRotationMatrix();
    multMatrix(t);
    glScaled(r, r, r);
    glCallList(g.ball);
    glPopMatrix();
  }
  drawRobots(options);
}

Scene::~Scene() = default;  // display lists die with their context

}  // namespace simswift::camera
