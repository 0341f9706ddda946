// The whole-wall camera and the sort-first tile projection of WireGL §3.2: every tile renders
// with the same camera, with a translate-and-scale prepended to the projection so that the tile
// sees exactly its rectangle of the logical canvas, pixel centre for pixel centre.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "tilelayout/geometry.hpp"

namespace l2 {

struct Canvas {
  int width = 0, height = 0;  // the whole logical canvas, mullions included
};

struct Camera {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // maps the whole canvas to NDC [-1, 1]^2
};

// A perspective camera that frames a sphere (centre, radius) on the whole canvas, whatever its
// aspect ratio. Deterministic: depends only on its arguments.
Camera frame_sphere(const Canvas& canvas, glm::vec3 centre, float radius);

// The matrix prepended to the projection for a tile rendering canvas rectangle `r` (canvas
// rows top to bottom): NDC of the rectangle's edges in the whole-canvas projection map to
// [-1, 1]. Scales by canvas/tile size and translates by whole pixels, so a tile's pixel centres
// coincide with whole-canvas pixel centres. Depth and w are untouched, so depth tests agree.
glm::dmat4 tile_matrix(const Canvas& canvas, const Rect& r);

// Where a point in clip space lands on the canvas, in canvas pixels (x right, y down).
// Only meaningful for clip.w > 0.
glm::dvec2 clip_to_canvas(const Canvas& canvas, const glm::dvec4& clip);

}  // namespace l2
