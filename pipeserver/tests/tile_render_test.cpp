// Tile projection maths on real OSMesa renders: a tile drawn as the window of the whole canvas
// draws it must equal the matching crop of the whole-canvas render exactly, for every scene,
// for tiles at awkward offsets and sizes; drawn at another place (its own window), it need not.
#include <gtest/gtest.h>

#include "pipeserver/gl_context.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/scan_out.hpp"
#include "pipeserver/tile_renderer.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

using test::crop;

// Canvas rectangle `r` drawn as the window of the whole canvas draws it, the rest black.
RgbImage tile_in_window(const Canvas& canvas, const Rect& r, Scene& scene, int frame) {
  const Rect window{0, 0, canvas.width, canvas.height};
  GlContext context(window.w, window.h);
  scene.set_frame(frame);
  TileRenderer renderer(scene, canvas);
  renderer.draw_tile(r, window);
  context.finish();
  RgbImage image(window.w, window.h);
  scan_out(context.rgba(), window.w, window.h, image.bytes());
  return crop(image, r);
}

class TileRender : public ::testing::TestWithParam<std::string> {};

TEST_P(TileRender, TileEqualsCropOfWholeRender) {
  const Canvas canvas{150, 90};
  auto scene = make_scene(GetParam(), test::small_options());
  const RgbImage whole = render_canvas_rect(canvas, {0, 0, 150, 90}, *scene, 7);
  long lit = 0;
  for (int y = 0; y < whole.height(); ++y)
    for (int x = 0; x < whole.width(); ++x) lit += whole.at(x, y) != Rgb{} ? 1 : 0;
  ASSERT_GT(lit, 500) << "the scene should cover a good part of the canvas";
  // Odd sizes and offsets, tiles across the middle, a one-pixel-wide tile.
  for (const Rect r : {Rect{0, 0, 75, 45}, Rect{37, 11, 61, 53}, Rect{74, 20, 1, 50},
                       Rect{100, 45, 50, 45}, Rect{53, 33, 29, 17}}) {
    const auto diff = test::compare(tile_in_window(canvas, r, *scene, 7), crop(whole, r));
    EXPECT_EQ(diff.pixels_differing, 0) << "tile " << r.x << "," << r.y << " " << r.w << "x" << r.h
                                        << " max diff " << diff.max_channel_diff;
  }
}

// What the window rule is for: the same tile rendered as a window of its own (the projection
// scaled to it, its own viewport) goes through other float operands, and some colours round to
// the neighbouring level.
TEST(TileRender, ATileInItsOwnWindowIsNotBitExact) {
  const Canvas canvas{150, 90};
  long differing = 0;
  for (const std::string& name : {std::string("mesh"), std::string("isosurface")}) {
    SceneOptions options = test::small_options();
    if (name == "mesh") options.fit = "fill";  // the model large on the 5:3 canvas, as before
    auto scene = make_scene(name, options);
    const RgbImage whole = render_canvas_rect(canvas, {0, 0, 150, 90}, *scene, 7);
    for (const Rect r : {Rect{0, 0, 75, 45}, Rect{37, 11, 61, 53}, Rect{100, 45, 50, 45}}) {
      differing +=
          test::compare(render_canvas_rect(canvas, r, *scene, 7), crop(whole, r)).pixels_differing;
    }
  }
  EXPECT_GT(differing, 0);
}

INSTANTIATE_TEST_SUITE_P(AllScenes, TileRender,
                         ::testing::Values("mesh", "strips", "isosurface", "patches"));

}  // namespace
}  // namespace l2
