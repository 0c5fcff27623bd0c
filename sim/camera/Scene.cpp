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

constexpr int kSphereSlices = 32, kSphereStacks = 16;   // robot spheres
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
  std::vector<std::pair<const MeshData*, GLuint>> mesh_lists;
};

Scene::Scene(const FieldConfig& field, SceneOptions options) : field_(field), options_(std::move(options)) {
  if (options_.team_colours.empty()) throw std::invalid_argument("SceneOptions: team_colours is empty");
}

Scene::~Scene() = default;  // display lists die with their context

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

void Scene::preloadModel(const NaoModel& model) {
  for (const auto& link : model.links())
    for (const auto& v : link.visuals)
      if (v.type == ShapeType::Mesh) mesh(v.mesh, link.name);
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
  glNewList(g.sphere, GL_COMPILE);
  emitSphere(kSphereSlices, kSphereStacks, false);
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

void Scene::drawShape(const simswift::ShapeSpec& s, const std::string& link) const {
  glColor4d(s.rgba[0], s.rgba[1], s.rgba[2], s.rgba[3]);
  glPushMatrix();
  multMatrix(s.origin.isometry());
  switch (s.type) {
    case ShapeType::Box:
      glScaled(s.size.x(), s.size.y(), s.size.z());
      glCallList(gl_->cube);
      break;
    case ShapeType::Sphere:
      glScaled(s.radius, s.radius, s.radius);
      glCallList(gl_->sphere);
      break;
    case ShapeType::Cylinder:
      glScaled(s.radius, s.radius, s.length);
      glCallList(gl_->cylinder);
      break;
    case ShapeType::Capsule:
      glPushMatrix();
      glScaled(s.radius, s.radius, s.length);
      glCallList(gl_->cylinder);
      glPopMatrix();
      for (double z : {-s.length / 2, s.length / 2}) {
        glPushMatrix();
        glTranslated(0, 0, z);
        glScaled(s.radius, s.radius, s.radius);
        glCallList(gl_->sphere);
        glPopMatrix();
      }
      break;
    case ShapeType::Mesh: {
      const MeshData* m = &mesh(s.mesh, link);
      GLuint list = 0;
      for (const auto& ml : gl_->mesh_lists)
        if (ml.first == m) list = ml.second;
      if (list == 0) {
        list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glBegin(GL_TRIANGLES);
        for (size_t i = 0; i < m->positions.size(); ++i) {
          glNormal3f(m->normals[i].x(), m->normals[i].y(), m->normals[i].z());
          glVertex3f(m->positions[i].x(), m->positions[i].y(), m->positions[i].z());
        }
        glEnd();
        glEndList();
        gl_->mesh_lists.emplace_back(m, list);
      }
      glCallList(list);
      break;
    }
  }
  glPopMatrix();
}

void Scene::drawRobot(int index, const RobotDrawState& robot, const DrawOptions& options) const {
  const NaoModel& model = *robot.model;
  const auto& links = model.links();
  if (robot.link_poses.size() != links.size())
    throw std::invalid_argument("Scene: robot " + std::to_string(index) + " has " +
                                std::to_string(robot.link_poses.size()) + " link poses for " +
                                std::to_string(links.size()) + " links");
  const int nteams = static_cast<int>(options_.team_colours.size());
  const Eigen::Vector3f& jersey = options_.team_colours[((robot.team % nteams) + nteams) % nteams];
  for (size_t li = 0; li < links.size(); ++li) {
    if (index == options.hide_robot && static_cast<int>(li) == options.hide_link) continue;
    glPushMatrix();
    multMatrix(robot.link_poses[li]);
    for (const auto& v : links[li].visuals) drawShape(v, links[li].name);
    if (options_.draw_jerseys && static_cast<int>(li) == model.rootLink()) {
      // Jersey: a band around the torso's first box visual (or a NAO-sized
      // default), slightly proud of it so it shows on every side.
      Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
      Eigen::Vector3d size(0.09, 0.12, 0.16);
      at.translation() = Eigen::Vector3d(-0.008, 0, 0.045);
      for (const auto& v : links[li].visuals)
        if (v.type == ShapeType::Box) {
          at = v.origin.isometry();
          size = v.size;
          break;
        }
      glPushMatrix();
      multMatrix(at);
      glTranslated(0, 0, 0.1 * size.z());
      glScaled(size.x() + 0.006, size.y() + 0.006, 0.4 * size.z());
      colour(jersey);
      glCallList(gl_->cube);
      glPopMatrix();
    }
    glPopMatrix();
  }
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
  for (size_t i = 0; i < robots.size(); ++i)
    if (robots[i].model) drawRobot(static_cast<int>(i), robots[i], options);
}

}  // namespace simswift::camera
