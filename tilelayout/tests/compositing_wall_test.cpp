// [depth] and [overlay] of a wall file (docs/wall-file.md) and how the planner deals depth
// layers and the overlay to pipeservers. Expected values worked out by hand from the rules.
#include <gtest/gtest.h>

#include <string>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

// Two 100x80 displays, 10-pixel mullion (canvas 210x80), a grid of 50x40 tiles: 10 logical
// tiles, each on one display (the one at canvas x 100 loses 100..109 to the mullion, the one at
// 200 is 10 wide), so 10 display tiles. Line numbers matter.
const std::string kBase =
    "[display_grid]\n"             // 1
    "columns = 2\n"                // 2
    "rows = 1\n"                   // 3
    "width = 100\n"                // 4
    "height = 80\n"                // 5
    "mullion_x = 10\n"             // 6
    "[tiling]\n"                   // 7
    "kind = \"grid\"\n"            // 8
    "tile_width = 50\n"            // 9
    "tile_height = 40\n"           // 10
    "[pipeservers]\n"              // 11
    "count = 4\n"                  // 12
    "framebuffer_width = 420\n"    // 13
    "framebuffer_height = 200\n";  // 14

std::string error_of(const std::string& text) {
  try {
    plan_layout(parse_wall(text, "walls/t.toml"));
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

std::string with_count(int count) {
  std::string text = kBase;
  text.replace(text.find("count = 4"), 9, "count = " + std::to_string(count));
  return text;
}

TEST(DepthWall, TwoLayersOfTwoPipeservers) {
  const TileLayout layout = plan_layout(parse_wall(kBase + "[depth]\nlayers = 2\n", "t.toml"));
  EXPECT_EQ(layout.wall.depth_layers, 2);
  ASSERT_EQ(layout.pipeservers.size(), 4u);
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(layout.pipeservers[s].layer, s / 2) << s;
    EXPECT_EQ(layout.pipeservers[s].layers, 2) << s;
  }
  // Every display tile once a layer, all DEPTH; layer 1's tile of pipeserver s + 2.
  const std::size_t per_layer = layout.tiles.size() / 2;
  ASSERT_EQ(layout.tiles.size(), 2 * per_layer);
  for (std::size_t i = 0; i < per_layer; ++i) {
    EXPECT_EQ(layout.tiles[i].compositing, Compositing::Depth);
    EXPECT_EQ(layout.tiles[i + per_layer].on_display, layout.tiles[i].on_display);
    EXPECT_LT(layout.tile_pipeserver[i], 2);
    EXPECT_EQ(layout.tile_pipeserver[i + per_layer], layout.tile_pipeserver[i] + 2);
  }
  // Round-robin over the two pipeservers of a layer: logical tiles 0, 2, 4, ... to the first.
  EXPECT_EQ(layout.tile_pipeserver[0], 0);
  EXPECT_EQ(layout.pipeservers[2].tiles.size(), layout.pipeservers[0].tiles.size());
}

TEST(DepthWall, AllLayersIsSortLast) {
  const TileLayout layout =
      plan_layout(parse_wall(with_count(2) + "[depth]\nlayers = \"all\"\n", "t.toml"));
  EXPECT_EQ(layout.wall.depth_layers, kAllLayers);
  ASSERT_EQ(layout.pipeservers.size(), 2u);
  EXPECT_EQ(layout.pipeservers[1].layer, 1);
  EXPECT_EQ(layout.pipeservers[1].layers, 2);
  // Both render every display tile.
  EXPECT_EQ(layout.pipeservers[0].tiles.size(), 10u);
  EXPECT_EQ(layout.pipeservers[1].tiles.size(), 10u);
}

TEST(DepthWall, BadLayersAreOneLineErrors) {
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = 0\n"),
            "walls/t.toml:16: depth.layers: must be 1..4 or \"all\", got 0");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = 5\n"),
            "walls/t.toml:16: depth.layers: must be 1..4 or \"all\", got 5");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = 3\n"),
            "walls/t.toml:16: depth.layers: 3 layers do not share 4 pipeservers evenly: 1, 2 "
            "or 4");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = \"most\"\n"),
            "walls/t.toml:16: depth.layers: must be 1..4 or \"all\", got \"most\"");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = true\n"),
            "walls/t.toml:16: depth.layers: must be an integer or \"all\", got a boolean");
  EXPECT_EQ(error_of(kBase + "[depth]\n"),
            "walls/t.toml:15: depth.layers: missing (required): a number of layers or \"all\"");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayer = 2\n"),
            "walls/t.toml:16: depth.layer: unknown key: did you mean layers? (valid here: layers)");
  EXPECT_EQ(error_of("depth = 2\n" + kBase),
            "walls/t.toml:1: depth: must be a table, got an integer");
}

TEST(DepthWall, DepthTilesThatDoNotFitNameTheirPayload) {
  // A DEPTH tile of 50 columns takes 4 + 100 columns: four fit a row of 420, none a row of 100.
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = 2\n"), "no error");
  std::string narrow = kBase;
  narrow.replace(narrow.find("framebuffer_width = 420"), 23, "framebuffer_width = 100");
  // What would fit counts the payloads too: pipeserver 0 gets tiles of 50, 40, 10, 50 and 50
  // columns, 104 + 84 + 24 + 104 + 104 = 420 in one row.
  EXPECT_EQ(error_of(narrow + "[depth]\nlayers = 2\n"),
            "walls/t.toml:14: pipeserver 0: tile 0 (display 0, 50x40 at 0,0, DEPTH) does not fit "
            "the 100x200 framebuffer: needs 104 columns, 4 too many; what would fit, each alone: "
            "[tiling] tile_width = 43 with tile_height = 40; framebuffer_width = 104");
}

const std::string kOverlay =
    "[overlay]\n"        // 15
    "display = 1\n"      // 16
    "x = 10\n"           // 17
    "y = 20\n"           // 18
    "width = 30\n"       // 19
    "height = 15\n"      // 20
    "key = 0x00ff00\n";  // 21

TEST(Overlay, TheLastPipeserverRendersItAloneAsAKeyTile) {
  const TileLayout layout = plan_layout(parse_wall(kBase + kOverlay, "t.toml"));
  ASSERT_TRUE(layout.wall.overlay.has_value());
  ASSERT_EQ(layout.pipeservers.size(), 4u);
  ASSERT_EQ(layout.pipeservers[3].tiles.size(), 1u);
  const DisplayTile& t = layout.pipeservers[3].tiles[0].tile;
  EXPECT_EQ(t.compositing, Compositing::Key);
  EXPECT_EQ(t.key, 0x00FF00u);
  EXPECT_EQ(t.display, 1);
  EXPECT_EQ(t.on_display, (Rect{10, 20, 30, 15}));
  EXPECT_EQ(t.on_canvas, (Rect{120, 20, 30, 15}));  // display 1 starts at canvas x 110
  EXPECT_EQ(t.logical_tile, 10);                    // after the tiling's 10
  EXPECT_EQ(layout.logical_tiles.back(), t.on_canvas);
  // The other three share the 10 display tiles as COPY tiles.
  std::size_t shared = 0;
  for (int s = 0; s < 3; ++s) {
    for (const PackedTile& p : layout.pipeservers[s].tiles) {
      EXPECT_EQ(p.tile.compositing, Compositing::Copy);
      ++shared;
    }
  }
  EXPECT_EQ(shared, 10u);
}

TEST(Overlay, WithDepthLayersOfTheOtherPipeservers) {
  const TileLayout layout =
      plan_layout(parse_wall(with_count(3) + kOverlay + "[depth]\nlayers = \"all\"\n", "t.toml"));
  EXPECT_EQ(layer_count(layout.wall, 3), 2);
  EXPECT_EQ(layout.pipeservers[1].layer, 1);
  EXPECT_EQ(layout.pipeservers[2].layers, 1);  // the overlay renders the whole scene
  EXPECT_EQ(layout.pipeservers[2].tiles.size(), 1u);
}

TEST(Overlay, BadValuesAreOneLineErrors) {
  EXPECT_EQ(error_of(kBase + "[overlay]\ndisplay = 1\nx = 80\ny = 0\nwidth = 30\nheight = 10\n"),
            "walls/t.toml:15: overlay: 30x10 at 80,0 does not lie on display 1 (100x80)");
  EXPECT_EQ(error_of(kBase + "[overlay]\ndisplay = 2\nx = 0\ny = 0\nwidth = 1\nheight = 1\n"),
            "walls/t.toml:16: overlay.display: must be 0..1, got 2");
  EXPECT_EQ(error_of(kBase + "[overlay]\nx = 0\ny = 0\nwidth = 1\nheight = 1\nkey = 0x1000000\n"),
            "walls/t.toml:20: overlay.key: must be 0..16777215, got 16777216");
  EXPECT_EQ(error_of(kBase + "[overlay]\nx = 0\ny = 0\nwidth = 1\n"),
            "walls/t.toml:15: overlay.height: missing (required)");
  EXPECT_EQ(error_of(with_count(1) + kOverlay),
            "walls/t.toml:15: overlay: needs a pipeserver of its own besides those of the "
            "tiles: pipeservers.count must be at least 2, got 1");
  EXPECT_EQ(
      error_of(kBase + "[overlay]\nx = 0\ny = 0\nwidth = 1\nheight = 1\nkeys = 0\n"),
      "walls/t.toml:20: overlay.keys: unknown key: did you mean key? (valid here: display, x, y, "
      "width, height, key)");
}

}  // namespace
}  // namespace l2
