// Walls planned by tilelayout and routed back by the emulator: every display must show exactly
// the tile pixels placed directly where the plan says, and the background elsewhere.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "lightning2_emu/frame_builder.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr Rgb kBackground{3, 2, 1};

// What each display must show: the background, and every planned tile's pixels placed directly
// at their display position by `pixel(display, x, y)`.
template <class Pixel>
std::vector<RgbImage> place_tiles(const TileLayout& layout, Pixel&& pixel) {
  std::vector<RgbImage> displays;
  for (const Display& d : layout.wall.displays) {
    displays.emplace_back(d.width, d.height, kBackground);
  }
  for (const DisplayTile& t : layout.tiles) {
    const Rect& r = t.on_display;
    for (int y = r.y; y < r.bottom(); ++y) {
      for (int x = r.x; x < r.right(); ++x) displays[t.display].set(x, y, pixel(t.display, x, y));
    }
  }
  return displays;
}

void expect_routed(const Wall& wall, const std::vector<RgbImage>& frames,
                   const std::vector<RgbImage>& expected, int workers, const std::string& name) {
  WorkerPool pool(workers);
  Router router(Mesh::fit(wall.pipeserver_count, static_cast<int>(wall.displays.size()),
                          {wall.board_max_width, wall.board_max_height}),
                display_specs(wall), pool, kBackground);
  std::vector<InputFrame> views;
  for (const RgbImage& f : frames) views.push_back(InputFrame::of(f));
  const RouteReport report = router.route(views);
  EXPECT_EQ(report.errors().total(), 0u) << name;
  for (const Display& d : wall.displays) {
    const RgbImage& shown = router.display(router.index_of_display(d.id)).back();
    ASSERT_EQ(shown, expected[d.id]) << name << ": display " << d.id;
  }
}

// `tilelayout --scanout` frames of every example wall rebuild the test pattern exactly.
TEST(WallRoundTrip, ExampleWallScanoutsRebuildTheTestPattern) {
  int walls = 0;
  for (const auto& entry : std::filesystem::directory_iterator(L2_WALLS_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    const Wall wall = load_wall(entry.path());
    if (wall.mesh_count > 1) continue;  // one mesh's routing here; tilelayout's tests do several
    ++walls;
    const TileLayout layout = plan_layout(wall);
    std::vector<RgbImage> frames;
    const bool parity = walls % 2 == 1;  // both parities over the set of walls
    for (const PipeserverPlan& s : layout.pipeservers) frames.push_back(test_frame(s, parity));
    expect_routed(wall, frames,
                  place_tiles(layout, [](int d, int x, int y) { return test_pattern(d, x, y); }), 2,
                  entry.path().filename().string());
  }
  EXPECT_GE(walls, 5);
}

Wall random_wall(std::mt19937& rng) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  Wall wall;
  wall.name = "random";
  const int columns = uni(1, 3), rows = uni(1, 2);
  const int mullion = uni(0, 12);
  int y = 0;
  for (int r = 0; r < rows; ++r) {
    int x = 0, row_height = 0;
    for (int c = 0; c < columns; ++c) {
      Display d;
      d.id = static_cast<int>(wall.displays.size());
      d.width = uni(40, 360);
      d.height = uni(30, 240);
      d.canvas_x = x;
      d.canvas_y = y + uni(0, 6);
      d.swap_group = uni(0, 1);
      x += d.width + mullion;
      row_height = std::max(row_height, d.canvas_y - y + d.height);
      wall.canvas_width = std::max(wall.canvas_width, d.canvas_x + d.width);
      wall.displays.push_back(d);
    }
    y += row_height + mullion;
  }
  wall.canvas_height = y - mullion;
  switch (uni(0, 2)) {
    case 0:
      wall.tiling.kind = TilingKind::Grid;
      wall.tiling.tile_width = uni(8, 200);
      wall.tiling.tile_height = uni(8, 150);
      break;
    case 1:
      wall.tiling.kind = TilingKind::KdSplit;
      wall.tiling.tile_count = uni(1, 40);
      break;
    default:
      wall.tiling.kind = TilingKind::Strips;
      wall.tiling.strip_count = uni(1, 12);
      wall.tiling.substrip_count = uni(1, 6);
  }
  wall.assignment = static_cast<AssignmentPolicy>(uni(0, 4));
  wall.pipeserver_count = uni(1, 8);
  wall.framebuffer_width = wall.board_max_width = uni(400, 1280);
  wall.framebuffer_height = wall.board_max_height = uni(300, 1024);
  return wall;
}

// Random walls, tilings and assignments; input frames built here from the plan with
// pack_tiles + draw_headers and tile pixels filled by this test.
TEST(WallRoundTrip, RandomWallsRouteToTheDirectlyPlacedTilePixels) {
  std::mt19937 rng(4242);
  int routed = 0;
  for (int attempt = 0; attempt < 400 && routed < 40; ++attempt) {
    const Wall wall = random_wall(rng);
    TileLayout layout;
    try {
      layout = plan_layout(wall);
    } catch (const LayoutError&) {
      continue;  // tiles that do not fit the framebuffers: a planning error, not ours
    }
    std::vector<RgbImage> frames;
    for (int s = 0; s < wall.pipeserver_count; ++s) {
      std::vector<DisplayTile> tiles;
      for (std::size_t t = 0; t < layout.tiles.size(); ++t) {
        if (layout.tile_pipeserver[t] == s) tiles.push_back(layout.tiles[t]);
      }
      const PipeserverPlan plan =
          pack_tiles(s, wall.framebuffer_width, wall.framebuffer_height, tiles);
      RgbImage fb(wall.framebuffer_width, wall.framebuffer_height);
      draw_headers(plan, (attempt & 1) != 0, fb);
      for (const PackedTile& p : plan.tiles) {
        const Rect& r = p.tile.on_display;
        for (int y = 0; y < r.h; ++y) {
          for (int x = 0; x < r.w; ++x) {
            fb.set(p.fb_x + x, p.fb_y + y, testing::pattern(p.tile.display, r.x + x, r.y + y));
          }
        }
      }
      frames.push_back(std::move(fb));
    }
    expect_routed(wall, frames, place_tiles(layout, testing::pattern), 1 + attempt % 3,
                  "random wall " + std::to_string(attempt));
    if (::testing::Test::HasFatalFailure()) return;
    ++routed;
  }
  EXPECT_GE(routed, 30);
}

}  // namespace
}  // namespace l2
