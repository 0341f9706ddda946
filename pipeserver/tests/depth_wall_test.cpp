// Pipeservers of depth walls and overlays (spec §7): what the DEPTH and KEY strips carry, and
// that the mesh's composite of the layers shows what one render of the whole scene shows.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "strip_headers/scanline_parser.hpp"

#include "pipeserver/depth_out.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "verify/verify_run.hpp"

namespace l2 {
namespace {

// One 64x48 display, one tile, rendered as `layers` by as many pipeservers, and with an
// overlay a pipeserver more.
TileLayout depth_wall(int pipeservers, const std::string& extra = "") {
  const std::string text =
      "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 64\nheight = 48\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 64\ntile_height = 48\n"
      "[pipeservers]\ncount = " +
      std::to_string(pipeservers) +
      "\nframebuffer_width = 132\nframebuffer_height = 48\n"
      "[depth]\nlayers = \"all\"\n" +
      extra;
  return plan_layout(parse_wall(text, "depth.toml"));
}

std::vector<RgbImage> render_all(const TileLayout& layout, Scene& scene, int frame,
                                 bool sparse = true) {
  std::vector<RgbImage> frames;
  for (int s = 0; s < static_cast<int>(layout.pipeservers.size()); ++s) {
    Pipeserver ps(layout, s);
    ps.set_sparse_depth(sparse);
    frames.push_back(ps.render_frame(frame, scene));
  }
  return frames;
}

std::uint32_t value(Rgb c) {
  return std::uint32_t{c.r} << 16 | std::uint32_t{c.g} << 8 | c.b;
}

// The depth pixels of the single tile (colour at 4..67, depth at 68..131).
std::vector<std::uint32_t> depths(const RgbImage& frame) {
  std::vector<std::uint32_t> out;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) out.push_back(value(frame.at(68 + x, y)));
  return out;
}

TEST(DepthWall, LayersSendTheirDepthAndOnlyLayerZeroItsClear) {
  const TileLayout layout = depth_wall(2);
  auto scene = make_scene("mesh", test::small_options());
  const std::vector<RgbImage> frames = render_all(layout, *scene, 3, false);
  long drawn[2] = {0, 0};
  for (int layer = 0; layer < 2; ++layer) {
    const std::vector<std::uint32_t> d = depths(frames[layer]);
    for (std::size_t i = 0; i < d.size(); ++i) {
      const Rgb colour = frames[layer].at(4 + static_cast<int>(i % 64), static_cast<int>(i / 64));
      if (d[i] < kFarDepth - 1) {
        ++drawn[layer];
        continue;
      }
      // Nothing drawn: the clear colour (black for the mesh), at FFFFFE from layer 0 so that
      // it shows, at the far plane from the others.
      EXPECT_EQ(d[i], layer == 0 ? kFarDepth - 1 : kFarDepth) << layer << " " << i;
      EXPECT_EQ(colour, Rgb{}) << layer << " " << i;
    }
  }
  // Each layer draws its half of the bunny: both cover part of the tile, neither all of it.
  for (long n : drawn) {
    EXPECT_GT(n, 100);
    EXPECT_LT(n, 64 * 48);
  }
}

TEST(DepthWall, TheClearColourShowsWhereNoLayerDraws) {
  // The swap scene draws nothing and clears each frame to its own colour: on a depth wall the
  // display shows that colour only because layer 0 sends its clear nearer than the far plane.
  const TileLayout layout = depth_wall(3);
  auto scene = make_scene("swap");
  for (int frame : {0, 5}) {
    const std::vector<RgbImage> frames = render_all(layout, *scene, frame);
    const std::vector<RgbImage> shown = route_on_wall(layout.wall, frames);
    const RgbImage want = render_reference(layout, 0, *scene, frame);
    EXPECT_NE(want.at(0, 0), Rgb{});
    EXPECT_EQ(test::compare(shown[0], want).pixels_differing, 0) << "frame " << frame;
  }
}

TEST(DepthWall, TheCompositeOfTheLayersIsTheWholeSceneRendered) {
  const TileLayout layout = depth_wall(3);
  for (const char* name : {"mesh", "isosurface"}) {
    auto scene = make_scene(name, test::small_options());
    const std::vector<RgbImage> shown = route_on_wall(layout.wall, render_all(layout, *scene, 2));
    const RgbImage want = render_reference(layout, 0, *scene, 2);
    EXPECT_EQ(test::compare(shown[0], want).pixels_differing, 0) << name;
  }
}

// DEPTH pixels and SKIP headers in a frame, as the mesh parses it.
struct Parsed {
  long depth_pixels = 0, skips = 0;
  std::uint64_t errors = 0;
};
Parsed parse(const RgbImage& frame) {
  Parsed p;
  StripErrorCounts errors;
  for (int y = 0; y < frame.height(); ++y) {
    parse_scanline(frame.data() + y * frame.stride(), frame.width(), 3, errors,
                   [&](const ParsedStrip& s) {
                     if (s.is(ExtKind::Depth)) p.depth_pixels += s.length;
                     if (s.header.op == StripOp::Skip) ++p.skips;
                   });
  }
  p.errors = errors.total();
  return p;
}

TEST(SparseDepth, FramesSendOnlyWhatWasDrawnAndDisplaysStayTheSame) {
  // Sparse and dense frames of the same render: the sparse ones carry fewer DEPTH pixels (the
  // bunny leaves most of the tile clear) and route to byte-identical displays, for layer 0's
  // black clear (left out) and the swap scene's coloured one (sent), with an overlay too.
  const TileLayout plain = depth_wall(3);
  const TileLayout overlaid =
      depth_wall(4, "[overlay]\nx = 8\ny = 4\nwidth = 40\nheight = 30\nkey = 0x00ff00\n");
  for (const TileLayout* layout : {&plain, &overlaid}) {
    for (const char* name : {"mesh", "isosurface", "swap"}) {
      auto scene = make_scene(name, test::small_options());
      for (int frame : {1, 2}) {
        const std::vector<RgbImage> dense = render_all(*layout, *scene, frame, false);
        const std::vector<RgbImage> sparse = render_all(*layout, *scene, frame, true);
        long dense_pixels = 0, sparse_pixels = 0;
        for (std::size_t s = 0; s < dense.size(); ++s) {
          const Parsed d = parse(dense[s]), p = parse(sparse[s]);
          EXPECT_EQ(p.errors, 0u) << name << " pipeserver " << s;
          dense_pixels += d.depth_pixels;
          sparse_pixels += p.depth_pixels;
        }
        if (std::string(name) == "mesh") {
          EXPECT_LT(sparse_pixels * 2, dense_pixels) << name;
        }
        EXPECT_LE(sparse_pixels, dense_pixels) << name;
        const std::vector<RgbImage> want = route_on_wall(layout->wall, dense);
        const std::vector<RgbImage> got = route_on_wall(layout->wall, sparse);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t d = 0; d < want.size(); ++d) {
          EXPECT_TRUE(got[d] == want[d]) << name << " frame " << frame << " display " << d;
        }
      }
    }
  }
}

TEST(SparseDepth, LayerZeroSendsItsColouredClear) {
  // The swap scene draws nothing: layers behind 0 send SKIPs, layer 0 every pixel
  // (its clear is not the background), so the display shows the clear colour.
  const TileLayout layout = depth_wall(3);
  auto scene = make_scene("swap");
  const std::vector<RgbImage> frames = render_all(layout, *scene, 1);
  // The framebuffer has no room for a stamp strip, so the first tile's first scanline, where the
  // frame number goes instead, stays dense: 64 pixels, and a SKIP on each of the other 47.
  EXPECT_EQ(parse(frames[0]).depth_pixels, 64 * 48);
  EXPECT_EQ(parse(frames[1]).depth_pixels, 64);
  EXPECT_EQ(parse(frames[1]).skips, 47);
  EXPECT_EQ(parse(frames[2]).depth_pixels, 64);
}

TEST(Overlay, IsTheSceneOverItsKeyColour) {
  const TileLayout layout =
      depth_wall(3, "[overlay]\nx = 8\ny = 4\nwidth = 40\nheight = 30\nkey = 0x00ff00\n");
  auto scene = make_scene("mesh", test::small_options());
  Pipeserver ps(layout, 2);
  const RgbImage& frame = ps.render_frame(1, *scene);
  long keyed = 0, drawn = 0;
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) ++(frame.at(4 + x, y) == Rgb{0, 255, 0} ? keyed : drawn);
  }
  EXPECT_GT(keyed, 0);
  EXPECT_GT(drawn, 0);
  // Routed over the layers, it changes nothing: where it is opaque it shows what they do.
  const std::vector<RgbImage> shown = route_on_wall(layout.wall, render_all(layout, *scene, 1));
  EXPECT_EQ(test::compare(shown[0], render_reference(layout, 0, *scene, 1)).pixels_differing, 0);
}

}  // namespace
}  // namespace l2
