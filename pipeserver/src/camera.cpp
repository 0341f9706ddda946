#include "pipeserver/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

namespace l2 {

namespace {
constexpr float kFovY = 0.6981317f;  // 40 degrees
}

Camera frame_sphere(const Canvas& canvas, glm::vec3 centre, float radius) {
  const float aspect = static_cast<float>(canvas.width) / static_cast<float>(canvas.height);
  // The narrower field of view decides how far back the camera stands.
  const float half_y = kFovY / 2;
  const float half_x = std::atan(std::tan(half_y) * aspect);
  const float distance = radius * 1.08f / std::sin(std::min(half_x, half_y));
  const glm::vec3 eye = centre + glm::vec3(0.0f, 0.0f, distance);
  Camera cam;
  cam.view = glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
  cam.projection = glm::perspective(kFovY, aspect, std::max(distance - 2 * radius, 0.01f),
                                    distance + 2 * radius);
  return cam;
}

glm::dmat4 tile_matrix(const Canvas& canvas, const Rect& r) {
  const double cw = canvas.width, ch = canvas.height;
  const double sx = cw / r.w, sy = ch / r.h;
  // Centre of the rectangle in whole-canvas NDC; canvas row 0 is NDC y = +1.
  const double cx = (2.0 * r.x + r.w) / cw - 1.0;
  const double cy = 1.0 - (2.0 * r.y + r.h) / ch;
  glm::dmat4 m(1.0);
  m[0][0] = sx;
  m[1][1] = sy;
  // Column 3 multiplies clip w: x' = sx * (x - cx * w).
  m[3][0] = -sx * cx;
  m[3][1] = -sy * cy;
  return m;
}

glm::dvec2 clip_to_canvas(const Canvas& canvas, const glm::dvec4& clip) {
  const double nx = clip.x / clip.w, ny = clip.y / clip.w;
  return {(nx + 1.0) * 0.5 * canvas.width, (1.0 - ny) * 0.5 * canvas.height};
}

}  // namespace l2
