// Tile projection maths on real OSMesa renders: a tile rendered alone must equal the matching
// crop of the whole-canvas render, for every scene, for tiles at awkward offsets and sizes.
#include <gtest/gtest.h>

#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

RgbImage crop(const RgbImage& img, const Rect& r) {
  RgbImage out(r.w, r.h);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) out.set(x, y, img.at(r.x + x, r.y + y));
  return out;
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
    const RgbImage tile = render_canvas_rect(canvas, r, *scene, 7);
    const auto diff = test::compare(tile, crop(whole, r));
    // The same triangle projected for another rectangle goes through different float
    // operands, so a colour can round to the neighbouring level (README: Reassembly tolerance):
    // one such pixel per tile, never more than one level, never a coverage or depth change.
    EXPECT_LE(diff.pixels_differing, 1) << "tile " << r.x << "," << r.y << " " << r.w << "x" << r.h
                                        << " max diff " << diff.max_channel_diff;
    EXPECT_EQ(diff.pixels_beyond_one, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllScenes, TileRender,
                         ::testing::Values("mesh", "strips", "isosurface", "patches"));

}  // namespace
}  // namespace l2
