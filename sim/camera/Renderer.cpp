#include "sim/camera/Renderer.hpp"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace simswift::camera {

namespace {
std::atomic<uint64_t> g_next_id{1};
std::string g_renderer_name = "(none)";

// The OpenGL projection for a pinhole camera with these intrinsics, column
// major. GL eye frame: x right, y up, looking down -z. Maps pixel u (from
// the left) to window x = u and pixel v (from the top) to the row v of a
// buffer stored top row first (OSMESA_Y_UP = 0).
void projection(const Intrinsics& k, double n, double f, double out[16]) {
  std::memset(out, 0, 16 * sizeof(double));
  const double w = k.width, h = k.height;
  out[0] = 2 * k.fx / w;              // (0,0)
  out[5] = 2 * k.fy / h;              // (1,1)
  out[8] = 1 - 2 * k.cx / w;          // (0,2)
  out[9] = 2 * k.cy / h - 1;          // (1,2)
  out[10] = -(f + n) / (f - n);       // (2,2)
  out[11] = -1;                       // (3,2)
  out[14] = -2 * f * n / (f - n);     // (2,3)
}
}  // namespace

Renderer::Renderer() : id_(g_next_id++) {
  setenv("LP_NUM_THREADS", "1", /*overwrite=*/0);
  ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx_) throw std::runtime_error("Renderer: OSMesaCreateContextExt failed (is libosmesa6 installed?)");
  makeCurrent(640, 480);
  if (const GLubyte* name = glGetString(GL_RENDERER)) g_renderer_name = reinterpret_cast<const char*>(name);
}

Renderer::~Renderer() {
  if (ctx_) OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_));
}

const char* Renderer::rendererName() { return g_renderer_name.c_str(); }

void Renderer::makeCurrent(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("Renderer: bad image size " + std::to_string(width) + "x" + std::to_string(height));
  OSMesaContext c = static_cast<OSMesaContext>(ctx_);
  if (width != width_ || height != height_ || OSMesaGetCurrentContext() != c) {
    buffer_.resize(size_t(width) * height * 4);
    if (!OSMesaMakeCurrent(c, buffer_.data(), GL_UNSIGNED_BYTE, width, height))
      throw std::runtime_error("Renderer: OSMesaMakeCurrent failed");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 = top of the image
    width_ = width;
    height_ = height;
  }
}

void Renderer::render(const Scene& scene, const CameraView& view, uint8_t* rgb) {
  const Intrinsics& k = view.camera.intrinsics;
  makeCurrent(k.width, k.height);
  glViewport(0, 0, k.width, k.height);
  const Eigen::Vector3f& sky = scene.options().sky;
  glClearColor(sky.x(), sky.y(), sky.z(), 1);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // Fixed state, set every frame so nothing leaks between views.
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_NORMALIZE);  // shapes are drawn from unit primitives scaled non-uniformly
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat ambient[4] = {0.65f, 0.65f, 0.65f, 1};
  const GLfloat diffuse[4] = {0.45f, 0.45f, 0.45f, 1};
  const GLfloat none[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, none);
  glEnable(GL_LIGHT0);

  double p[16];
  projection(k, view.near_clip, view.far_clip, p);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(p);

  // World -> camera frame (x forward, y left, z up) -> GL eye frame
  // (x right = -y, y up = z, z back = -x).
  Eigen::Matrix4d to_gl = Eigen::Matrix4d::Zero();
  to_gl(0, 1) = -1;
  to_gl(1, 2) = 1;
  to_gl(2, 0) = -1;
  to_gl(3, 3) = 1;
  const Eigen::Matrix4d modelview = to_gl * view.camera.pose.inverse().matrix();
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(modelview.data());

  scene.draw(id_, view.draw);
  glFinish();

  const size_t n = size_t(k.width) * k.height;
  const uint8_t* src = buffer_.data();
  for (size_t i = 0; i < n; ++i) {
    rgb[i * 3 + 0] = src[i * 4 + 0];
    rgb[i * 3 + 1] = src[i * 4 + 1];
    rgb[i * 3 + 2] = src[i * 4 + 2];
  }
}

std::vector<uint8_t> Renderer::render(const Scene& scene, const CameraView& view) {
  std::vector<uint8_t> out(size_t(view.camera.intrinsics.width) * view.camera.intrinsics.height * 3);
  render(scene, view, out.data());
  return out;
}

}  // namespace simswift::camera
