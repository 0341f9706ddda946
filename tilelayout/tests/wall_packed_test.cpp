// Packed stereo in the wall file (`stereo = "side-by-side"` or `"top-bottom"`; docs/wall-file.md,
// "Stereo walls"): which canvas rectangle each half of a display shows, the plan's tiles split at
// each display's middle, and every refusal's exact line naming file, line and field.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

#include "tilelayout/plan_report.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_folder.hpp"

namespace l2::packed_wall_test {
namespace {

// Two 100x80 displays side by side; tiles 30x50 cross both displays' middles. Line numbers
// matter.
std::string packed_wall(const std::string& mode, const std::string& first_display_keys = "") {
  return "stereo = \"" + mode + "\"\n" +                              // 1
         "[[display]]\nwidth = 100\nheight = 80\nx = 0\ny = 0\n" +    // 2-6
         first_display_keys +                                         //
         "[[display]]\nwidth = 100\nheight = 80\nx = 100\ny = 0\n" +  //
         "[tiling]\nkind = \"grid\"\ntile_width = 30\ntile_height = 50\n"
         "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 400\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_wall(text, "walls/p.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WallPacked, SideBySideHalvesShowTheWholeDisplayEach) {
  const Wall w = parse_wall(packed_wall("side-by-side"), "walls/p.toml");
  EXPECT_EQ(w.stereo.mode, StereoMode::SideBySide);
  ASSERT_EQ(w.displays.size(), 2u);  // no twins: each display shows both eyes
  EXPECT_EQ(w.displays[1].eye, Eye::None);
  EXPECT_TRUE(eye_pairs(w).empty());
  const auto parts = display_parts(w.stereo, w.displays[1]);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].on_canvas, (Rect{100, 0, 50, 80}));
  EXPECT_EQ(parts[0].eye, Eye::Left);
  EXPECT_EQ(parts[0].seen, (Rect{100, 0, 100, 80}));
  EXPECT_EQ(parts[1].on_canvas, (Rect{150, 0, 50, 80}));
  EXPECT_EQ(parts[1].eye, Eye::Right);
  EXPECT_EQ(parts[1].seen, (Rect{100, 0, 100, 80}));
}

TEST(WallPacked, TopBottomHalvesShowTheWholeDisplayEach) {
  const Wall w = parse_wall(packed_wall("top-bottom"), "walls/p.toml");
  const auto parts = display_parts(w.stereo, w.displays[0]);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].on_canvas, (Rect{0, 0, 100, 40}));
  EXPECT_EQ(parts[0].eye, Eye::Left);
  EXPECT_EQ(parts[1].on_canvas, (Rect{0, 40, 100, 40}));
  EXPECT_EQ(parts[1].eye, Eye::Right);
  EXPECT_EQ(parts[1].seen, (Rect{0, 0, 100, 80}));
}

TEST(WallPacked, AMonoDisplayIsOnePartOfItself) {
  const Wall w = parse_wall(packed_wall("side-by-side"), "walls/p.toml");
  const auto parts = display_parts(StereoSpec{}, w.displays[1]);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].on_canvas, (Rect{100, 0, 100, 80}));
  EXPECT_EQ(parts[0].seen, parts[0].on_canvas);
  EXPECT_EQ(parts[0].eye, Eye::None);
}

// Every tile lies in one half; together the tiles of a display cover it exactly once.
void expect_tiles_in_halves(const Wall& w) {
  const TileLayout layout = plan_layout(w);
  for (const Display& d : w.displays) {
    long long area = 0;
    for (const DisplayTile& t : layout.tiles) {
      if (t.display != d.id) continue;
      area += t.on_canvas.area();
      int holding = 0;
      for (const DisplayPart& p : display_parts(w.stereo, d))
        holding += intersect(p.on_canvas, t.on_canvas) == t.on_canvas;
      EXPECT_EQ(holding, 1) << "display " << d.id << " tile at " << t.on_canvas.x << ","
                            << t.on_canvas.y;
    }
    EXPECT_EQ(area, 100 * 80) << "display " << d.id;
  }
}

TEST(WallPacked, TilesAreSplitAtEachDisplaysMiddle) {
  // Side by side: columns cut at 0,30,60,90 and the displays' edges and middles 50, 100, 150:
  // display 0 gets x 0-30, 30-50, 50-60, 60-90, 90-100 (5), display 1 100-120, 120-150,
  // 150-180, 180-200 (4); rows at 0 and 50: 2 each.
  const Wall side = parse_wall(packed_wall("side-by-side"), "walls/p.toml");
  EXPECT_EQ(make_logical_tiles(side).size(), 14u);
  const TileLayout layout = plan_layout(side);
  int first = 0, second = 0;
  for (const DisplayTile& t : layout.tiles) (t.display == 0 ? first : second) += 1;
  EXPECT_EQ(first, 10);
  EXPECT_EQ(second, 8);
  expect_tiles_in_halves(side);
  // Top and bottom: rows cut at 0, 50 and the middle 40: 3 rows; columns at 0,30,60,90 and the
  // display edge 100: 4 on display 0, and 100-120,120-150,150-180,180-200 on display 1.
  const Wall top = parse_wall(packed_wall("top-bottom"), "walls/p.toml");
  const TileLayout top_layout = plan_layout(top);
  int top_first = 0;
  for (const DisplayTile& t : top_layout.tiles) top_first += t.display == 0;
  EXPECT_EQ(top_first, 12);
  expect_tiles_in_halves(top);
}

TEST(WallPacked, ThePlanSaysWhichHalfShowsWhichEye) {
  const std::string side = format_plan(plan_layout(parse_wall(packed_wall("side-by-side"), "p")));
  EXPECT_NE(side.find("display 1: 100x80 at canvas 100,0, swap group 0, left eye in its left "
                      "half, right eye in its right (side-by-side stereo): 100.0% covered"),
            std::string::npos)
      << side;
  const std::string top = format_plan(plan_layout(parse_wall(packed_wall("top-bottom"), "p")));
  EXPECT_NE(top.find("display 0: 100x80 at canvas 0,0, swap group 0, left eye in its top half, "
                     "right eye in its bottom (top-bottom stereo): 100.0% covered"),
            std::string::npos)
      << top;
}

TEST(WallPacked, RefusesAnOddSideInOneLine) {
  std::string odd = packed_wall("side-by-side");
  odd.replace(odd.find("width = 100"), 11, "width = 101");
  EXPECT_EQ(error_of(odd),
            "walls/p.toml:2: display 0: side-by-side stereo: width 101 is odd: each eye takes "
            "exactly half of it");
  std::string tall = packed_wall("top-bottom");
  tall.replace(tall.rfind("height = 80"), 11, "height = 81");
  EXPECT_EQ(error_of(tall),
            "walls/p.toml:7: display 1: top-bottom stereo: height 81 is odd: each eye takes "
            "exactly half of it");
}

TEST(WallPacked, RefusesATurnedDisplayAnEyeAndBlendInOneLine) {
  EXPECT_EQ(error_of(packed_wall("side-by-side", "rotation = 180\n")),
            "walls/p.toml:2: display 0: side-by-side stereo: rotation and flip are not "
            "supported (each eye's half is in the panel's own raster)");
  EXPECT_EQ(error_of(packed_wall("top-bottom", "flip = \"horizontal\"\n")),
            "walls/p.toml:2: display 0: top-bottom stereo: rotation and flip are not supported "
            "(each eye's half is in the panel's own raster)");
  EXPECT_EQ(error_of(packed_wall("side-by-side", "eye = \"left\"\n")),
            "walls/p.toml:2: display 0: eye is only for a wall with stereo = \"passive\"");
  // Displays overlapping by 10 columns: blend would have edges to ramp.
  std::string overlapping = "blend = \"linear\"\n" + packed_wall("side-by-side");
  overlapping.replace(overlapping.find("x = 100"), 7, "x = 90");
  EXPECT_EQ(error_of(overlapping),
            "walls/p.toml:1: blend: stereo walls do not support blending yet");
  EXPECT_EQ(error_of(packed_wall("top-bottom") + "[depth]\nlayers = 2\n"),
            "walls/p.toml:21: depth: stereo walls do not support depth compositing yet");
  EXPECT_EQ(error_of(packed_wall("side-by-side") + "[balance]\nmode = \"strips\"\n"),
            "walls/p.toml:20: balance: stereo walls do not support balancing yet");
}

class WallPackedWarp : public WallFolder {
 protected:
  WallPackedWarp() : WallFolder("packed") {}
};

TEST_F(WallPackedWarp, RefusesAWarpInOneLine) {
  // An identity warp of the 4x2 display: each pixel's own centre, bottom row first.
  std::string pfm = "PF\n4 2\n-1.0\n";
  for (const int row : {1, 0}) {
    for (int x = 0; x < 4; ++x) {
      for (const float v :
           {(static_cast<float>(x) + 0.5f) / 4, (static_cast<float>(row) + 0.5f) / 2, 0.0f}) {
        const auto bits = std::bit_cast<std::uint32_t>(v);
        for (int b = 0; b < 4; ++b) pfm.push_back(static_cast<char>(bits >> (8 * b) & 0xff));
      }
    }
  }
  write("calibration/w.pfm", pfm);
  EXPECT_EQ(
      error_of("stereo = \"side-by-side\"\n" + one_display_wall("warp = \"calibration/w.pfm\"")),
      wall_file() +
          ":2: display 0: side-by-side stereo: warp is not supported (it would move "
          "pixels across the halves)");
}

}  // namespace
}  // namespace l2::packed_wall_test
