#include "pipeserver/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

namespace l2 {

namespace {

// How far back the camera stands to frame the sphere on the canvas (CameraOptions::distance 0).
float framing_distance(float radius, float fov_y, float aspect, bool whole) {
  const float half_y = fov_y / 2;
  const float half_x = std::atan(std::tan(half_y) * aspect);
  // The sphere fits the short side, unless that leaves more of the long side empty than a
  // quarter of the short side at each end: then it spans the long side less those quarters.
  const float half_short = std::min(half_x, half_y), half_long = std::max(half_x, half_y);
  const float half_fill = std::atan(std::tan(half_long) - std::tan(half_short) / 2);
  const float half = whole ? half_short : std::max(half_short, half_fill);
  return radius * 1.08f / std::sin(half);
}

}  // namespace

Camera frame_sphere(const Canvas& canvas, glm::vec3 centre, float radius,
                    const CameraOptions& options, bool whole) {
  const float aspect = static_cast<float>(canvas.width) / static_cast<float>(canvas.height);
  const float fov_y = glm::radians(options.fov);
  const float distance = options.distance > 0 ? radius * options.distance
                                              : framing_distance(radius, fov_y, aspect, whole);
  const glm::vec3 eye = centre + glm::vec3(0.0f, 0.0f, distance);
  Camera cam;
  cam.view = glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
  cam.projection = glm::perspective(fov_y, aspect, std::max(distance - 2 * radius, 0.01f),
                                    distance + 2 * radius);
  return cam;
}

Camera eye_camera(const Camera& mono, const StereoEye& eye, glm::vec3 centre) {
  if (eye.eye == Eye::None) return mono;
  // The eye's x in the mono camera's space: left of it is negative.
  const float side = eye.eye == Eye::Left ? -1.0f : 1.0f;
  const auto half = static_cast<float>(eye.stereo.eye_separation / 2);
  const float convergence = eye.stereo.convergence > 0 ? static_cast<float>(eye.stereo.convergence)
                                                       : -(mono.view * glm::vec4(centre, 1.0f)).z;
  Camera cam = mono;
  cam.view = glm::translate(glm::mat4(1.0f), glm::vec3(-side * half, 0.0f, 0.0f)) * mono.view;
  // x_clip += k·w_clip: NDC x moves by k, which brings the convergence plane back to the mono
  // camera's place; clip w is the distance in front of the eye.
  glm::mat4 shift(1.0f);
  shift[3][0] = side * mono.projection[0][0] * half / convergence;
  cam.projection = shift * mono.projection;
  return cam;
}

glm::mat4 orbit_matrix(float degrees_per_frame, int frame, glm::vec3 centre) {
  // In double, so that a whole number of degrees a frame gives whole angles at any frame.
  const auto degrees =
      static_cast<float>(std::fmod(static_cast<double>(degrees_per_frame) * frame, 360.0));
  if (degrees == 0) return glm::mat4(1.0f);
  const glm::mat4 turn =
      glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
  if (centre == glm::vec3(0.0f)) return turn;
  return glm::translate(glm::mat4(1.0f), centre) * turn * glm::translate(glm::mat4(1.0f), -centre);
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
