// Tile projection maths without rendering: the tile matrix maps the tile's canvas rectangle
// exactly onto NDC [-1, 1], pixel centres onto pixel centres.
#include <gtest/gtest.h>

#include "pipeserver/bucketing.hpp"
#include "pipeserver/camera.hpp"

namespace l2 {
namespace {

// NDC of a canvas point after the tile matrix, for a point given in whole-canvas NDC (w = 1).
glm::dvec2 through(const glm::dmat4& m, double ndc_x, double ndc_y) {
  const glm::dvec4 v = m * glm::dvec4(ndc_x, ndc_y, 0.25, 1.0);
  return {v.x / v.w, v.y / v.w};
}

TEST(TileMatrix, WholeCanvasIsIdentity) {
  const glm::dmat4 m = tile_matrix({1920, 1080}, {0, 0, 1920, 1080});
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_DOUBLE_EQ(m[c][r], c == r ? 1.0 : 0.0);
}

TEST(TileMatrix, TileEdgesMapToNdcEdges) {
  // Canvas 100 x 50; tile columns 25..74, rows 0..24 (the top half, middle columns).
  // Whole-canvas NDC: x 25 -> -0.5, x 75 -> 0.5; row 0 -> y +1, row 25 -> y 0.
  const glm::dmat4 m = tile_matrix({100, 50}, {25, 0, 50, 25});
  const auto lo = through(m, -0.5, 0.0), hi = through(m, 0.5, 1.0);
  EXPECT_NEAR(lo.x, -1.0, 1e-12);
  EXPECT_NEAR(lo.y, -1.0, 1e-12);
  EXPECT_NEAR(hi.x, 1.0, 1e-12);
  EXPECT_NEAR(hi.y, 1.0, 1e-12);
}

TEST(TileMatrix, PixelCentresCoincide) {
  // Canvas pixel (30, 7) centre: whole NDC x = (30.5 / 100) * 2 - 1 = -0.39,
  // y = 1 - (7.5 / 50) * 2 = 0.7. In the tile (25, 0, 50, 25) it is tile pixel (5, 7), whose
  // centre is tile NDC x = (5.5 / 50) * 2 - 1 = -0.78, y = 1 - (7.5 / 25) * 2 = 0.4.
  const auto p = through(tile_matrix({100, 50}, {25, 0, 50, 25}), -0.39, 0.7);
  EXPECT_NEAR(p.x, -0.78, 1e-12);
  EXPECT_NEAR(p.y, 0.4, 1e-12);
}

TEST(TileMatrix, LeavesDepthAndWAlone) {
  const glm::dmat4 m = tile_matrix({640, 480}, {13, 200, 77, 31});
  const glm::dvec4 v = m * glm::dvec4(0.3, -0.2, 0.7, 2.5);
  EXPECT_DOUBLE_EQ(v.z, 0.7);
  EXPECT_DOUBLE_EQ(v.w, 2.5);
}

TEST(ClipToCanvas, CornersAndCentre) {
  const Canvas c{200, 100};
  const auto tl = clip_to_canvas(c, {-2.0, 2.0, 0.0, 2.0});  // NDC (-1, 1): top-left corner
  EXPECT_DOUBLE_EQ(tl.x, 0.0);
  EXPECT_DOUBLE_EQ(tl.y, 0.0);
  const auto mid = clip_to_canvas(c, {0.0, 0.0, 0.0, 1.0});
  EXPECT_DOUBLE_EQ(mid.x, 100.0);
  EXPECT_DOUBLE_EQ(mid.y, 50.0);
}

Rect unit_cube_footprint(const Canvas& c, const CameraOptions& options = {}) {
  const Camera cam = frame_sphere(c, {0, 0, 0}, 1.0f, options);
  const Box cube{glm::vec3(-0.57f), glm::vec3(0.57f)};  // a cube inside the unit sphere
  return canvas_footprint(c, cam.projection * cam.view, cube);
}

TEST(FrameSphere, SphereFitsInsideCanvasesUpTo3To2) {
  for (const Canvas c : {Canvas{1280, 1024}, Canvas{1300, 980}, Canvas{1024, 1280},
                         Canvas{1440, 1000}, Canvas{500, 500}}) {
    const Rect fp = unit_cube_footprint(c);
    EXPECT_GT(fp.x, 0);
    EXPECT_GT(fp.y, 0);
    EXPECT_LT(fp.right(), c.width);
    EXPECT_LT(fp.bottom(), c.height);
  }
}

// A sphere that fitted the short side of a wide wall left its outer displays black: it now
// spans most of the long side and is cropped across the short one.
TEST(FrameSphere, WideAndTallCanvasesAreFilledAlongTheLongSide) {
  const Rect wide = unit_cube_footprint(Canvas{4000, 500});
  EXPECT_EQ(wide.y, 0);  // footprints are clipped to the canvas
  EXPECT_EQ(wide.bottom(), 500);
  EXPECT_GT(wide.x, 0);
  EXPECT_LT(wide.right(), 4000);
  EXPECT_GT(wide.w, 1000);  // a quarter of the long side; it fitted the 500 rows before
  const Rect tall = unit_cube_footprint(Canvas{500, 4000});
  EXPECT_EQ(tall.x, 0);
  EXPECT_EQ(tall.right(), 500);
  EXPECT_GT(tall.h, 1000);
}

TEST(FrameSphere, DistanceAndFieldOfViewAreOptions) {
  const Camera near =
      frame_sphere(Canvas{400, 300}, {0, 0, 0}, 2.0f, {.distance = 5, .orbit = {}, .fov = 40});
  EXPECT_FLOAT_EQ(near.view[3][2], -10.0f);  // five radii of 2 in front of the eye
  const Camera wide =
      frame_sphere(Canvas{400, 300}, {0, 0, 0}, 1.0f, {.distance = 0, .orbit = {}, .fov = 90});
  EXPECT_NEAR(wide.projection[1][1], 1.0f, 1e-6f);  // cot(45 degrees)
  // The default field of view is 40 degrees.
  EXPECT_NEAR(frame_sphere(Canvas{400, 300}, {0, 0, 0}, 1.0f).projection[1][1], 2.7474774f, 1e-6f);
}

TEST(OrbitMatrix, TurnsAboutTheVerticalAxisThroughTheCentre) {
  const glm::vec4 x = orbit_matrix(90.0f, 1, {0, 0, 0}) * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(x.x, 0.0f, 1e-6f);
  EXPECT_NEAR(x.z, -1.0f, 1e-6f);
  // Half a turn about (1, 5, 0): the centre stays, the origin goes to (2, 0, 0).
  const glm::mat4 half = orbit_matrix(60.0f, 3, {1, 5, 0});
  const glm::vec4 c = half * glm::vec4(1, 5, 0, 1);
  EXPECT_NEAR(c.x, 1.0f, 1e-5f);
  EXPECT_NEAR(c.y, 5.0f, 1e-5f);
  const glm::vec4 o = half * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(o.x, 2.0f, 1e-5f);
  EXPECT_NEAR(o.z, 0.0f, 1e-5f);
  EXPECT_EQ(orbit_matrix(3.0f, 120, {0, 0, 0}), glm::mat4(1.0f));  // a whole turn
}

}  // namespace
}  // namespace l2
