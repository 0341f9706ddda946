// Pipeservers of depth walls and overlays (spec §7): what the DEPTH and KEY strips carry, and
// that the mesh's composite of the layers shows what one render of the whole scene shows.
#include <gtest/gtest.h>

#include <string>
#include <vector>

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

std::vector<RgbImage> render_all(const TileLayout& layout, Scene& scene, int frame) {
  std::vector<RgbImage> frames;
  for (int s = 0; s < static_cast<int>(layout.pipeservers.size()); ++s) {
    Pipeserver ps(layout, s);
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
  const std::vector<RgbImage> frames = render_all(layout, *scene, 3);
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
