// Edge blending generated from the wall (tilelayout/blend_map.hpp, docs/wall-file.md, "Blending
// overlapping projectors"): `blend` as the wall file writes it and every refusal's exact line;
// the ramps and weights of small walls worked out by hand from the documented rule (a ramp
// factor min(1, d / width) per ramped edge, d the distance of the pixel's centre from the edge,
// the product normalised over the displays showing the pixel); the weights in a mirrored
// panel's own raster; the tables by the documented formula; and what tilelayout says.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tilelayout/blend_map.hpp"
#include "tilelayout/plan_report.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

// Two 8x4 projectors overlapping by 4 columns: display 0 covers canvas columns 0..7, display 1
// columns 4..11. Line numbers matter: errors below name them.
const std::string kPair =
    "BLEND\n"                     // 1
    "[[display]]\n"               // 2
    "width = 8\n"                 // 3
    "height = 4\n"                // 4
    "x = 0\n"                     // 5
    "y = 0\n"                     // 6
    "[[display]]\n"               // 7
    "width = 8\n"                 // 8
    "height = 4\n"                // 9
    "x = X1\n"                    // 10
    "y = 0\n"                     // 11
    "FLIP\n"                      // 12
    "[tiling]\n"                  // 13
    "kind = \"grid\"\n"           // 14
    "tile_width = 4\n"            // 15
    "tile_height = 4\n"           // 16
    "[pipeservers]\n"             // 17
    "count = 1\n"                 // 18
    "framebuffer_width = 40\n"    // 19
    "framebuffer_height = 20\n";  // 20

std::string two_projectors(const std::string& blend, const std::string& flip = "", int x1 = 4) {
  std::string text = kPair;
  text.replace(text.find("BLEND"), 5, blend);
  text.replace(text.find("X1"), 2, std::to_string(x1));
  text.replace(text.find("FLIP"), 4, flip);
  return text;
}

Wall blend_wall(const std::string& text) {
  return parse_wall(text, "w.toml");
}

std::string blend_error(const std::string& text) {
  try {
    blend_wall(text);
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BlendWall, ReadsLinearAGammaAndASection) {
  EXPECT_FALSE(blend_wall(two_projectors("")).blend.on);
  const Wall linear = blend_wall(two_projectors("blend = \"linear\""));
  EXPECT_TRUE(linear.blend.on);
  EXPECT_EQ(linear.blend.gamma, 1.0);
  const Wall gamma = blend_wall(two_projectors("blend = { gamma = 2.2 }"));
  EXPECT_TRUE(gamma.blend.on);
  EXPECT_EQ(gamma.blend.gamma, 2.2);
  const Wall section = blend_wall(two_projectors("") + "[blend]\ngamma = 2\n");
  EXPECT_TRUE(section.blend.on);
  EXPECT_EQ(section.blend.gamma, 2.0);
}

TEST(BlendWall, RefusalsNameFileLineAndField) {
  EXPECT_EQ(blend_error(two_projectors("blend = \"cubic\"")),
            "w.toml:1: blend: must be \"linear\" or { gamma = 1..4 }, got \"cubic\"");
  EXPECT_EQ(blend_error(two_projectors("blend = 2")),
            "w.toml:1: blend: must be \"linear\" or { gamma = 1..4 }, got an integer");
  EXPECT_EQ(blend_error(two_projectors("blend = { gamma = 0.5 }")),
            "w.toml:1: blend.gamma: must be a number 1..4, got 0.5");
  EXPECT_EQ(blend_error(two_projectors("blend = { gamma = \"2.2\" }")),
            "w.toml:1: blend.gamma: must be a number 1..4, got a string");
  EXPECT_EQ(blend_error(two_projectors("blend = {}")),
            "w.toml:1: blend.gamma: required: a number 1..4");
  EXPECT_NE(blend_error(two_projectors("blend = { gama = 2.2 }")).find("w.toml:1: blend.gama"),
            std::string::npos);
  // Side by side, no overlap: nothing to blend.
  EXPECT_EQ(blend_error(two_projectors("blend = \"linear\"", "", 8)),
            "w.toml:1: blend: no two displays overlap: nothing to blend (a negative mullion, or "
            "[[display]] rectangles that overlap, declare an overlap)");
}

TEST(BlendMap, TwoProjectorsRampAcrossTheOverlap) {
  const Wall wall = blend_wall(two_projectors("blend = \"linear\""));
  const BlendRamps zero = blend_ramps(wall, 0), one = blend_ramps(wall, 1);
  EXPECT_EQ(zero.right, 4);
  EXPECT_EQ(zero.left + zero.top + zero.bottom, 0);
  EXPECT_EQ(one.left, 4);
  EXPECT_EQ(one.right + one.top + one.bottom, 0);
  // Overlap columns 4..7, 4 wide: display 0 weighs (8 - (u + 0.5)) / 4, display 1
  // (u + 0.5 - 4) / 4, in 4096ths: 3.5/4 = 3584, 2.5/4 = 2560, 1.5/4 = 1536, 0.5/4 = 512.
  const int zero_at[12] = {4096, 4096, 4096, 4096, 3584, 2560, 1536, 512, 0, 0, 0, 0};
  for (int u = 0; u < 12; ++u) {
    for (int v = 0; v < 4; ++v) {
      const std::vector<int> w = blend_weights_at(wall, u, v);
      EXPECT_EQ(w[0], zero_at[u]) << u;
      EXPECT_EQ(w[1], u < 4 ? 0 : 4096 - zero_at[u]) << u;
    }
  }
  const std::vector<std::uint16_t> map0 = blend_weights(wall, 0), map1 = blend_weights(wall, 1);
  ASSERT_EQ(map0.size(), 32u);
  ASSERT_EQ(map1.size(), 32u);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      EXPECT_EQ(map0[static_cast<std::size_t>(y * 8 + x)], zero_at[x]);
      EXPECT_EQ(map1[static_cast<std::size_t>(y * 8 + x)], 4096 - zero_at[4 + x]);
    }
  }
  // A wall that does not blend has no maps.
  EXPECT_TRUE(blend_weights(blend_wall(two_projectors("")), 0).empty());
}

TEST(BlendMap, AMirroredPanelsMapIsInItsOwnRaster) {
  // Display 1 flipped: its panel pixel x shows canvas column 4 + 7 - x.
  const Wall wall = blend_wall(two_projectors("blend = \"linear\"", "flip = \"horizontal\""));
  const std::vector<std::uint16_t> map1 = blend_weights(wall, 1);
  const int panel_row[8] = {4096, 4096, 4096, 4096, 3584, 2560, 1536, 512};
  for (int x = 0; x < 8; ++x) EXPECT_EQ(map1[static_cast<std::size_t>(8 + x)], panel_row[x]) << x;
}

TEST(BlendMap, CornersOfFourProjectorsMultiplyThenShare) {
  // Four 4x4 projectors overlapping by 2 both ways: canvas 6x6, every edge inside ramped over 2.
  const Wall wall = blend_wall(
      "blend = \"linear\"\n"
      "[display_grid]\ncolumns = 2\nrows = 2\nwidth = 4\nheight = 4\nmullion_x = -2\n"
      "mullion_y = -2\n[tiling]\nkind = \"grid\"\ntile_width = 2\ntile_height = 2\n"
      "[pipeservers]\ncount = 1\nframebuffer_width = 64\nframebuffer_height = 64\n");
  const BlendRamps r0 = blend_ramps(wall, 0), r3 = blend_ramps(wall, 3);
  EXPECT_EQ(r0.right, 2);
  EXPECT_EQ(r0.bottom, 2);
  EXPECT_EQ(r3.left, 2);
  EXPECT_EQ(r3.top, 2);
  // (3, 3), in all four: x factors 0.25 (display 0's right ramp: 4 - 3.5 over 2) and 0.75
  // (display 1's left: 3.5 - 2 over 2), y likewise; products 1/16, 3/16, 3/16, 9/16.
  EXPECT_EQ(blend_weights_at(wall, 3, 3), (std::vector<int>{256, 768, 768, 2304}));
  // (2, 3): x factors 0.75 and 0.25, y 0.25 and 0.75.
  EXPECT_EQ(blend_weights_at(wall, 2, 3), (std::vector<int>{768, 256, 2304, 768}));
  // (1, 3): left of display 1 and 3: display 0's x factor min(1, 2.5 / 2) = 1, y 0.25;
  // display 2's 1 and 0.75.
  EXPECT_EQ(blend_weights_at(wall, 1, 3), (std::vector<int>{1024, 0, 3072, 0}));
  EXPECT_EQ(blend_weights_at(wall, 0, 0), (std::vector<int>{4096, 0, 0, 0}));
}

// out = round(255 * (w * (in/255)^gamma)^(1/gamma)), halves up, as docs/wall-file.md writes it;
// at gamma 1 in whole numbers (in * weight / 4096 lands on exact halves, which doubles miss).
int by_formula(int in, double w, double gamma) {
  if (gamma == 1.0) return (2 * in * static_cast<int>(w * 4096) + 4096) / 8192;
  const long double light = w * std::pow(in / 255.0L, static_cast<long double>(gamma));
  return static_cast<int>(
      std::floor(255 * std::pow(light, 1 / static_cast<long double>(gamma)) + 0.5L));
}

TEST(BlendMap, TablesFollowTheFormula) {
  for (const double gamma : {1.0, 2.2}) {
    for (const int weight : {0, 1, 512, 1024, 2048, 3584, 4095, 4096}) {
      const ColourTable t = blend_table(weight, gamma);
      for (int in = 0; in < 256; ++in) {
        const int want = by_formula(in, weight / 4096.0, gamma);
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(t.channel[c][in], want) << "weight " << weight << " gamma " << gamma;
      }
    }
  }
  EXPECT_TRUE(blend_table(4096, 2.2).is_identity());
  EXPECT_EQ(blend_table(2048, 1.0).channel[0][1], 1);      // 0.5, half up
  EXPECT_EQ(blend_table(2048, 1.0).channel[0][255], 128);  // 127.5
  EXPECT_EQ(blend_table(2048, 2.2).channel[0][128], 93);   // 128 * 0.5^(1/2.2) = 93.28
}

TEST(BlendMap, DisplayTablesBlendThenMatchColour) {
  // Display 0 also adds 10 to red: each of its tables is the blend table, then +10.
  std::string text = two_projectors("blend = { gamma = 2.2 }");
  text.replace(text.find("y = 0\n"), 6, "y = 0\noffset = [10, 0, 0]\n");
  const Wall wall = blend_wall(text);
  const std::optional<TableMap> map = display_tables(wall, 0);
  ASSERT_TRUE(map);
  EXPECT_EQ(map->width, 8);
  EXPECT_EQ(map->height, 4);
  ASSERT_EQ(map->tables.size(), 5u);  // 4096 and the four overlap weights
  const ColourTable& full = map->tables[map->index[0]];
  EXPECT_EQ(full.channel[0][100], 110);
  EXPECT_EQ(full.channel[1][100], 100);
  const ColourTable& last = map->tables[map->index[7]];  // weight 512
  EXPECT_EQ(last.channel[0][128], by_formula(128, 512 / 4096.0, 2.2) + 10);
  EXPECT_EQ(last.channel[2][128], by_formula(128, 512 / 4096.0, 2.2));
  EXPECT_EQ(map->index[8], map->index[0]);  // row 1 starts at weight 4096 too
  EXPECT_FALSE(display_tables(blend_wall(two_projectors("")), 0));
}

TEST(BlendMap, TilelayoutSaysWhatEachDisplayBlends) {
  const std::string plan =
      format_plan(plan_layout(blend_wall(two_projectors("blend = { gamma = 2.2 }"))));
  EXPECT_NE(plan.find("; blend gamma 2.2 over 4 columns at the right edge\n"), std::string::npos)
      << plan;
  EXPECT_NE(plan.find("; blend gamma 2.2 over 4 columns at the left edge\n"), std::string::npos);
  const std::string linear =
      format_plan(plan_layout(blend_wall(two_projectors("blend = \"linear\""))));
  EXPECT_NE(linear.find("; blend linear over 4 columns at the right edge\n"), std::string::npos);
}

}  // namespace
}  // namespace l2
