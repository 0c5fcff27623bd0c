// What the cameras see: the field (carpet, painted lines, goals with nets),
// the robots (each link's URDF visual shapes, meshes through assimp) with a
// team-coloured jersey band on the torso, and a black-and-white ball whose
// patches make its rotation visible.
//
// The field part is built once from the FieldConfig; the robots and the ball
// are plain state the caller refreshes before each render (see
// RobotCameras::syncScene, which copies them from a World). Drawing uses
// legacy fixed-function OpenGL and needs a current context (Renderer).
//
// Frames and units: world (field) frame as in World.hpp, m, rad.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/nao_model/RobotModel.hpp"
#include "sim/world/FieldConfig.hpp"

namespace simswift::camera {

struct SceneOptions {
  // Jersey colours (RGB 0..1) by team number; team 0 blue, team 1 red. A
  // team beyond the list wraps around.
  std::vector<Eigen::Vector3f> team_colours{{0.10f, 0.25f, 0.90f}, {0.90f, 0.12f, 0.10f}};
  Eigen::Vector3f carpet{0.10f, 0.50f, 0.14f};
  Eigen::Vector3f lines{1.0f, 1.0f, 1.0f};
  Eigen::Vector3f sky{0.62f, 0.66f, 0.72f};  // background beyond the carpet
  // Folders searched for relative mesh paths (after the path as given);
  // "package://<pkg>/" prefixes are stripped first.
  std::vector<std::string> mesh_dirs;
  bool draw_net = true;
  bool draw_jerseys = true;  // team band on each robot's torso
};

// One robot's pose for drawing.
struct RobotDrawState {
  const RobotModel* model = nullptr;
  int team = 0;
  std::vector<Eigen::Isometry3d> link_poses;  // per model link, link frame in world
};

struct DrawOptions {
  // Skip one link of one robot: the camera's own head, which would otherwise
  // enclose the camera.
  int hide_robot = -1;
  int hide_link = -1;
};

class Scene {
 public:
  explicit Scene(const FieldConfig& field, SceneOptions options = {});
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const FieldConfig& field() const { return field_; }
  const SceneOptions& options() const { return options_; }

  // --- Dynamic state, refreshed by the caller before rendering.
  std::vector<RobotDrawState> robots;
  Eigen::Vector3d ball_position{0, 0, 0.05};                        // m, ball centre
  Eigen::Quaterniond ball_orientation = Eigen::Quaterniond::Identity();
  bool show_ball = true;

  // Loads every mesh a model's visuals name (cached by path). Throws
  // std::runtime_error naming the link and mesh if one cannot be found or
  // read. Called automatically on first draw; call it early to fail early.
  void preloadModel(const RobotModel& model);

  // Draws everything with the current GL context, whose modelview must hold
  // the world-to-eye transform. `context_id` identifies the context: display
  // lists are rebuilt when it changes.
  void draw(uint64_t context_id, const DrawOptions& options) const;

  // Goal post centres (m, field frame; x = goal line centre), the same
  // placement as the World's collision geometry: [goal 0..1][post 0..1],
  // goal 0 at -x, post 0 at -y.
  static Eigen::Vector2d goalPostCentre(const FieldConfig& field, int goal, int post);

 private:
  struct Gl;
  struct MeshData;
  const MeshData& mesh(const std::string& path, const std::string& link) const;
  void buildLists() const;
  struct LinkGeometry;
  const std::vector<LinkGeometry>& modelGeometry(const RobotModel& model) const;
  void drawRobots(const DrawOptions& options) const;

  FieldConfig field_;
  SceneOptions options_;
  mutable std::unique_ptr<Gl> gl_;
  mutable std::vector<std::pair<std::string, std::unique_ptr<MeshData>>> meshes_;
  // Per model (by address: a model must outlive the Scene's use of it).
  mutable std::vector<std::pair<const RobotModel*, std::vector<LinkGeometry>>> geometry_;
  mutable std::vector<Eigen::Vector3f> scratch_p_, scratch_n_;
  mutable std::vector<Eigen::Vector4f> scratch_c_;
};

}  // namespace simswift::camera
