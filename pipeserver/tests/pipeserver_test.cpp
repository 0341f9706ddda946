// Whole pipeservers on a small wall: header placement, frame parity, and reassembly of every
// display from the COPY strips equal to the reference render.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "header_at.hpp"
#include "pipeserver/pipeserver.hpp"
#include "strip_headers/strip_header.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

using test::header_at;

TEST(Pipeserver, HeadersSitInTheGapsOfEveryPackedTile) {
  const TileLayout layout = test::small_layout(2, 40, 32, 160, 120);
  Pipeserver ps(layout, 1);
  auto scene = make_scene("patches", test::small_options());
  const RgbImage& fb = ps.render_frame(3, *scene);
  ASSERT_EQ(fb.width(), 160);
  ASSERT_EQ(fb.height(), 120);
  ASSERT_FALSE(ps.plan().tiles.empty());
  for (const PackedTile& p : ps.plan().tiles) {
    const StripHeader h = header_at(fb, p.fb_x - 2, p.fb_y);
    EXPECT_EQ(h.op, StripOp::Copy);
    EXPECT_TRUE(h.frame);
    EXPECT_EQ(h.display, p.tile.display);
    EXPECT_EQ(h.x, p.tile.on_display.x);
    EXPECT_EQ(h.y, p.tile.on_display.y);
    EXPECT_EQ(h.width, p.tile.on_display.w);
    const StripHeader last = header_at(fb, p.fb_x - 2, p.fb_y + p.tile.on_display.h - 1);
    EXPECT_EQ(last.y, p.tile.on_display.y + p.tile.on_display.h - 1);
  }
  // Below the last packed row the frame is black.
  for (int y = ps.plan().used_height(); y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) ASSERT_EQ(fb.at(x, y), Rgb{});
}

TEST(Pipeserver, FrameParityAlternatesWithTheFrameNumber) {
  const TileLayout layout = test::small_layout(1, 68, 48, 160, 100);
  Pipeserver ps(layout, 0);
  auto scene = make_scene("mesh");
  for (int frame : {0, 1, 2, 7, 10}) {
    const auto r = test::reassemble(layout.wall, {ps.render_frame(frame, *scene)});
    EXPECT_EQ(r.parities_seen, std::vector<int>{frame % 2}) << "frame " << frame;
  }
}

TEST(Pipeserver, ReportsTimesAndOverlap) {
  const TileLayout layout = test::small_layout(1, 34, 24, 200, 200);
  Pipeserver ps(layout, 0);
  auto scene = make_scene("strips", test::small_options());
  ps.render_frame(0, *scene);
  const FrameTimes& t = ps.last_times();
  EXPECT_GT(t.render_ms, 0.0);
  EXPECT_GT(t.scanout_ms, 0.0);
  // Every tile's own time (the load balancer's measure, CPU time).
  ASSERT_EQ(t.tile_ms.size(), ps.plan().tiles.size());
  for (double ms : t.tile_ms) EXPECT_GT(ms, 0.0);
  EXPECT_GT(t.buckets.batches, 0);
  EXPECT_GE(t.buckets.tile_draws, t.buckets.batches);
  // Fewer draws than drawing every batch into every tile: bucketing saved something.
  EXPECT_LT(t.buckets.tile_draws,
            static_cast<long>(scene->batches().size() * ps.plan().tiles.size()));
  // The batches' footprints for the balancer: every batch (the whole cloud is in view) with
  // its triangles, on the canvas; as many draws as footprints touching the tiles.
  ASSERT_EQ(t.footprints.size(), scene->batches().size());
  double triangles = 0;
  long touching = 0;
  const Rect canvas{0, 0, layout.wall.canvas_width, layout.wall.canvas_height};
  for (const BatchFootprint& f : t.footprints) {
    EXPECT_EQ(intersect(f.on_canvas, canvas), f.on_canvas);
    triangles += f.triangles;
    for (const PackedTile& p : ps.plan().tiles)
      touching += overlaps(f.on_canvas, p.tile.on_canvas) ? 1 : 0;
  }
  EXPECT_DOUBLE_EQ(triangles, double(scene->triangle_count()));
  EXPECT_EQ(touching, t.buckets.tile_draws);
}

TEST(Pipeserver, ANewLayoutRendersAsAPipeserverMadeForIt) {
  // The same wall cut two ways (what the load balancer does between frames).
  const TileLayout before = test::small_layout(2, 40, 32, 160, 120);
  const TileLayout after = test::small_layout(2, 34, 24, 160, 120);
  Pipeserver moved(before, 1);
  auto scene = make_scene("patches", test::small_options());
  moved.render_frame(2, *scene);
  moved.set_layout(after);
  Pipeserver fresh(after, 1);
  const RgbImage a = moved.render_frame(3, *scene);
  const RgbImage b = fresh.render_frame(3, *scene);
  EXPECT_EQ(moved.plan().tiles.size(), fresh.plan().tiles.size());
  EXPECT_TRUE(a.bytes().size() == b.bytes().size() &&
              std::equal(a.bytes().begin(), a.bytes().end(), b.bytes().begin()));
  EXPECT_THROW(moved.set_layout(test::small_layout(2, 40, 32, 200, 120)), std::invalid_argument);
}

TEST(Pipeserver, RendersIntoACallersBufferEveryPixelAsIntoItsOwn) {
  const TileLayout layout = test::small_layout(2, 40, 32, 160, 120);
  Pipeserver ps(layout, 1);
  auto scene = make_scene("patches", test::small_options());
  // A buffer holding an older frame's bytes (as a DVI link's back frame does), one byte longer.
  std::vector<std::uint8_t> buffer(160 * 120 * 3 + 1, 0xA5);
  const std::span<std::uint8_t> out = ps.render_frame(3, *scene, buffer);
  EXPECT_EQ(out.data(), buffer.data());
  ASSERT_EQ(out.size(), 160u * 120u * 3u);
  EXPECT_EQ(buffer.back(), 0xA5);  // nothing past the frame
  const RgbImage& own = ps.render_frame(3, *scene);
  EXPECT_TRUE(std::equal(out.begin(), out.end(), own.bytes().begin()));
  EXPECT_EQ(test::reassemble(layout.wall, {own}).errors.total(), 0u);
}

TEST(Pipeserver, RefusesABufferSmallerThanAFrame) {
  const TileLayout layout = test::small_layout(2, 40, 32, 160, 120);
  Pipeserver ps(layout, 1);
  auto scene = make_scene("patches", test::small_options());
  std::vector<std::uint8_t> buffer(160 * 120 * 3 - 1);
  try {
    ps.render_frame(0, *scene, buffer);
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "pipeserver 1: frame buffer of 57599 bytes, a 160x120 frame needs 57600");
  }
}

TEST(Pipeserver, UnknownPipeserverIsAClearError) {
  const TileLayout layout = test::small_layout(2, 40, 32, 160, 120);
  try {
    Pipeserver ps(layout, 2);
    FAIL();
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "pipeserver 2 does not exist: the wall has 2 (0..1)");
  }
}

class Reassembles : public ::testing::TestWithParam<std::string> {};

TEST_P(Reassembles, EveryDisplayEqualsTheReferenceRender) {
  const TileLayout layout = test::small_layout(3, 40, 20, 120, 120);
  auto scene = make_scene(GetParam(), test::small_options());
  const int frame = 4;
  std::vector<RgbImage> frames;
  for (int s = 0; s < 3; ++s) {
    Pipeserver ps(layout, s);
    frames.push_back(ps.render_frame(frame, *scene));
  }
  const auto r = test::reassemble(layout.wall, frames);
  EXPECT_EQ(r.errors.total(), 0u);
  EXPECT_EQ(r.copied_pixels, 2 * 64 * 48);  // every display pixel arrives exactly once
  for (int d = 0; d < 2; ++d) {
    const RgbImage ref = render_reference(layout, d, *scene, frame);
    const auto diff = test::compare(r.displays[static_cast<std::size_t>(d)], ref);
    // Bit for bit: every tile is drawn as its display's window draws it (tile_renderer.hpp).
    EXPECT_EQ(diff.pixels_differing, 0) << "display " << d << " max diff " << diff.max_channel_diff;
  }
}

INSTANTIATE_TEST_SUITE_P(AllScenes, Reassembles,
                         ::testing::Values("mesh", "strips", "isosurface", "patches"));

// The swap scene colours its tiles only: no pixel outside them takes the frame's colour, which
// the mesh would read as strip headers in unused rows and columns.
TEST(Pipeserver, SwapSceneColoursTheTilesAndNothingElse) {
  const TileLayout layout = test::small_layout(2, 40, 32, 160, 120);
  Pipeserver ps(layout, 1);
  auto scene = make_scene("swap");
  const RgbImage& fb = ps.render_frame(3, *scene);
  const Rgb colour{(64 + 37 * 3) % 256, (128 + 101 * 3) % 256, (192 + 173 * 3) % 256};
  std::vector<int> owner(static_cast<std::size_t>(fb.width() * fb.height()), 0);  // 1 tile, 2 gap
  for (const PackedTile& p : ps.plan().tiles) {
    for (int y = p.fb_y; y < p.fb_y + p.tile.on_display.h; ++y) {
      for (int x = p.fb_x - 2; x < p.fb_x + p.tile.on_display.w; ++x) {
        owner[static_cast<std::size_t>(y * fb.width() + x)] = x < p.fb_x ? 2 : 1;
      }
    }
  }
  long wrong_tile = 0, wrong_outside = 0;
  for (int y = 0; y < fb.height(); ++y) {
    for (int x = 0; x < fb.width(); ++x) {
      const int o = owner[static_cast<std::size_t>(y * fb.width() + x)];
      if (o == 1) wrong_tile += !(fb.at(x, y) == colour);
      if (o == 0) wrong_outside += fb.at(x, y) == colour;
    }
  }
  EXPECT_EQ(wrong_tile, 0);
  EXPECT_EQ(wrong_outside, 0);
}

}  // namespace
}  // namespace l2
