// Sort-first bucketing: footprints, and on real renders, a batch outside a tile is not drawn
// into it.
#include <gtest/gtest.h>

#include "image/rgb_image.hpp"
#include "pipeserver/bucketing.hpp"
#include "pipeserver/gl_context.hpp"
#include "pipeserver/scan_out.hpp"
#include "pipeserver/tile_renderer.hpp"

namespace l2 {
namespace {

TEST(CanvasFootprint, OrthographicBoxMapsToItsPixelsPlusOne) {
  // Identity clip transform: NDC x -1..0 is canvas columns 0..50, NDC y 0..1 rows 0..25.
  const Rect fp = canvas_footprint({100, 50}, glm::mat4(1.0f), Box{{-1, 0, 0}, {0, 1, 0}});
  EXPECT_EQ(fp, (Rect{0, 0, 51, 26}));  // grown by one pixel, clipped to the canvas
  // x 0.25..0.5 is columns 62.5..75, y -0.25..-0.5 rows 31.25..37.5; rounded out, grown by one.
  const Rect inner =
      canvas_footprint({100, 50}, glm::mat4(1.0f), Box{{0.25f, -0.5f, 0}, {0.5f, -0.25f, 0}});
  EXPECT_EQ(inner, (Rect{61, 30, 15, 9}));
}

TEST(CanvasFootprint, BoxReachingBehindTheEyeCoversEverything) {
  glm::mat4 m(1.0f);
  m[2][3] = 1.0f;  // w = z + 1: the box below reaches w <= 0
  m[3][3] = 1.0f;
  EXPECT_EQ(canvas_footprint({100, 50}, m, Box{{-0.1f, -0.1f, -2}, {0.1f, 0.1f, 0}}),
            (Rect{0, 0, 100, 50}));
}

TEST(CanvasFootprint, EmptyBoxCoversNothing) {
  EXPECT_TRUE(canvas_footprint({100, 50}, glm::mat4(1.0f), Box::empty()).empty());
}

// One unlit white triangle around the canvas centre, with bounds the test chooses.
class OneTriangle : public Scene {
 public:
  explicit OneTriangle(Box bounds) {
    lit_ = false;
    Batch b;
    b.positions = {{-0.3f, -0.3f, 0}, {0.3f, -0.3f, 0}, {0, 0.3f, 0}};
    b.colours.assign(3, glm::vec3(1.0f));
    b.bounds = bounds;
    batches_.push_back(b);
  }
  const char* name() const override { return "one-triangle"; }
  void animate(int) override {}
};

struct TileResult {
  long lit_pixels = 0;
  BucketStats stats;
};

TileResult render_centre_tile(const Scene& scene) {
  const Canvas canvas{120, 80};
  const Rect tile{40, 20, 40, 40};  // the middle of the canvas, where the triangle is
  GlContext context(tile.w, tile.h);
  TileRenderer r(scene, canvas);
  r.draw_tile(tile, tile);
  context.finish();
  RgbImage img(tile.w, tile.h);
  scan_out(context.rgba(), tile.w, tile.h, img.bytes());
  TileResult out;
  out.stats = r.stats();
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) out.lit_pixels += img.at(x, y) == Rgb{255, 255, 255};
  return out;
}

TEST(Bucketing, BatchInsideTheTileIsDrawn) {
  const auto res = render_centre_tile(OneTriangle(Box{{-0.3f, -0.3f, 0}, {0.3f, 0.3f, 0}}));
  EXPECT_EQ(res.stats.tile_draws, 1);
  EXPECT_EQ(res.stats.batches, 1);
  EXPECT_GT(res.lit_pixels, 100);
}

TEST(Bucketing, BatchOutsideTheTileIsNotDrawnThere) {
  // The bounds claim the batch sits at the far left; the renderer trusts them and skips the
  // tile, so its geometry (really in the middle) never reaches the tile's pixels.
  const auto res = render_centre_tile(OneTriangle(Box{{-0.95f, -0.1f, 0}, {-0.9f, 0.1f, 0}}));
  EXPECT_EQ(res.stats.tile_draws, 0);
  EXPECT_EQ(res.lit_pixels, 0);
}

TEST(Bucketing, OverlapFactorIsDrawsPerBatch) {
  BucketStats s{4, 10};
  EXPECT_DOUBLE_EQ(s.overlap_factor(), 2.5);
  EXPECT_DOUBLE_EQ(BucketStats{}.overlap_factor(), 0.0);
}

}  // namespace
}  // namespace l2
