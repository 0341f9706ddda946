// The whole-wall camera and the sort-first tile projection of WireGL §3.2: every tile renders
// with the same camera, with a translate-and-scale prepended to the projection so that the tile
// sees exactly its rectangle of the logical canvas, pixel centre for pixel centre.
#pragma once

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "tilelayout/geometry.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct Canvas {
  int width = 0, height = 0;  // the whole logical canvas, mullions included
};

struct Camera {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // maps the whole canvas to NDC [-1, 1]^2
};

// `--camera-*` of pipeserver and l2wall run.
struct CameraOptions {
  // Eye to the scene's centre in scene radii; 0: framed to the canvas (frame_sphere).
  float distance = 0;
  // Degrees a frame the view orbits the scene about the vertical axis through its centre
  // (positive: the scene seems to turn counter-clockwise seen from above); unset: the scene's
  // own default (the mesh orbits, the generated scenes animate themselves).
  std::optional<float> orbit;
  float fov = 40;  // vertical field of view, degrees
};

// A perspective camera looking at a sphere (centre, radius) from +z. At distance 0 the sphere
// is framed on the whole canvas: it fits the canvas's short side, but spans at least the long
// side less a quarter of the short side at each end, so a wide wall is filled (the sphere
// cropped at top and bottom) instead of leaving its outer displays black; on canvases up to 3:2
// the whole sphere is in view. With `whole` (a model shown with --fit fit: seen whole, not
// sliced) it fits the short side on every canvas, the long side's ends left dark on a wide
// wall. A margin of 8% of the radius is kept either way. Deterministic: depends only on its
// arguments.
Camera frame_sphere(const Canvas& canvas, glm::vec3 centre, float radius,
                    const CameraOptions& options = {}, bool whole = false);

// The eye a tile is rendered for, and the wall's stereo camera (tilelayout/wall.hpp's
// StereoSpec); Eye::None: the mono camera.
struct StereoEye {
  Eye eye = Eye::None;
  StereoSpec stereo;
};

// One eye's camera: the mono camera's eye moved half the eye separation to its side, looking the
// same way, with its frustum shifted (off-axis, never turned in) so that the plane `convergence`
// in front of the eyes (default: through `centre`) lands where the mono camera draws it. A point
// at distance d then lies e·(1/convergence − 1/d)·P00 apart in NDC x between the eyes (right
// less left; P00 the projection's x scale). Eye::None gives `mono` itself, bit for bit.
Camera eye_camera(const Camera& mono, const StereoEye& eye, glm::vec3 centre);

// The orbit of frame `frame` as a model transform: a turn of degrees_per_frame x frame about the
// vertical axis through `centre`. The scenes' light is fixed to the eye, so turning the scene
// this way shows exactly what a camera orbiting it would.
glm::mat4 orbit_matrix(float degrees_per_frame, int frame, glm::vec3 centre);

// The matrix prepended to the projection for a tile rendering canvas rectangle `r` (canvas
// rows top to bottom): NDC of the rectangle's edges in the whole-canvas projection map to
// [-1, 1]. Scales by canvas/tile size and translates by whole pixels, so a tile's pixel centres
// coincide with whole-canvas pixel centres. Depth and w are untouched, so depth tests agree.
glm::dmat4 tile_matrix(const Canvas& canvas, const Rect& r);

// Where a point in clip space lands on the canvas, in canvas pixels (x right, y down).
// Only meaningful for clip.w > 0.
glm::dvec2 clip_to_canvas(const Canvas& canvas, const glm::dvec4& clip);

}  // namespace l2
