// Off-screen rendering with OSMesa (Mesa's software rasteriser, llvmpipe on
// Debian): no display, no GPU. One context per Renderer; create one per
// process (per thread that renders) and reuse it for every view.
//
// Determinism: llvmpipe's output does not depend on its thread count, but to
// keep a run on one core and rule out any doubt, the constructor sets
// LP_NUM_THREADS=1 in the environment before creating the context unless the
// caller already set it. No multisampling, no textures, fixed lighting:
// the same scene and view give the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/camera/CameraModel.hpp"
#include "sim/camera/Scene.hpp"

namespace simswift::camera {

struct CameraView {
  CameraModel camera;          // pose (camera frame in world) and intrinsics
  DrawOptions draw;            // e.g. hide the camera's own head
  double near_clip = 0.02;     // m
  double far_clip = 40.0;      // m
};

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders into `rgb` (width*height*3 bytes, top row first).
  void render(const Scene& scene, const CameraView& view, uint8_t* rgb);
  std::vector<uint8_t> render(const Scene& scene, const CameraView& view);

  static const char* rendererName();  // GL_RENDERER of the last context made

 private:
  void makeCurrent(int width, int height);

  void* ctx_ = nullptr;  // OSMesaContext
  uint64_t id_;
  std::vector<uint8_t> buffer_;  // RGBA colour buffer OSMesa draws into
  int width_ = 0, height_ = 0;
};

}  // namespace simswift::camera
