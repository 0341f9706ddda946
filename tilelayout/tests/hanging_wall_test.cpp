// Wall files of displays that hang turned or mirrored: `rotation` and `flip` per display and per
// grid, the canvas rectangles they cover, the tiles cut from them, and the one-line errors.
#include <gtest/gtest.h>

#include "tilelayout/plan_report.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

const std::string kHangingTail =
    "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 50\n"
    "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 300\n";

std::string hanging_error_of(const std::string& text) {
  try {
    parse_wall(text, "walls/h.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(HangingWall, GridOfPortraitPanelsStepsByTheTurnedSize) {
  // 100x60 panels at 90: each covers 60x100 of the canvas; the bezels are on the canvas.
  const Wall w = parse_wall(
      "[display_grid]\ncolumns = 3\nrows = 2\nwidth = 100\nheight = 60\nrotation = 90\n"
      "mullion_x = 8\nmullion_y = 4\n" +
          kHangingTail,
      "walls/h.toml");
  ASSERT_EQ(w.displays.size(), 6u);
  EXPECT_EQ(w.displays[0].width, 100);  // native, as the panel reports it
  EXPECT_EQ(w.displays[0].height, 60);
  EXPECT_EQ(w.displays[0].orientation, (Orientation{90, Flip::None}));
  EXPECT_EQ(w.displays[1].on_canvas(), (Rect{68, 0, 60, 100}));
  EXPECT_EQ(w.displays[5].on_canvas(), (Rect{136, 104, 60, 100}));
  EXPECT_EQ(w.canvas_width, 196);
  EXPECT_EQ(w.canvas_height, 204);
}

TEST(HangingWall, DisplayEntriesTakeRotationAndFlip) {
  const Wall w = parse_wall(
      "[[display]]\nwidth = 100\nheight = 60\nx = 0\ny = 0\nrotation = 270\n"
      "[[display]]\nwidth = 100\nheight = 60\nx = 70\ny = 0\nrotation = 180\n"
      "flip = \"horizontal\"\n"
      "[[display]]\nwidth = 100\nheight = 60\nx = 70\ny = 70\nflip = \"vertical\"\n" +
          kHangingTail,
      "walls/h.toml");
  EXPECT_EQ(w.displays[0].orientation, (Orientation{270, Flip::None}));
  EXPECT_EQ(w.displays[0].on_canvas(), (Rect{0, 0, 60, 100}));
  EXPECT_EQ(w.displays[1].orientation, (Orientation{180, Flip::Horizontal}));
  EXPECT_EQ(w.displays[1].on_canvas(), (Rect{70, 0, 100, 60}));
  EXPECT_EQ(w.displays[2].orientation, (Orientation{0, Flip::Vertical}));
  EXPECT_EQ(w.canvas_width, 170);
  EXPECT_EQ(w.canvas_height, 130);
}

TEST(HangingWall, TilesOfATurnedPanelAreInItsOwnRaster) {
  // One 100x60 panel at 90 covering canvas 60x100; the canvas tile (0,0 50x50) is its top-left,
  // which the panel shows in its top-right corner turned: panel x 0..49 (canvas y), y 10..59.
  const TileLayout layout = plan_layout(parse_wall(
      "[[display]]\nwidth = 100\nheight = 60\nx = 0\ny = 0\nrotation = 90\n" + kHangingTail,
      "h.toml"));
  ASSERT_FALSE(layout.tiles.empty());
  const DisplayTile& t = layout.tiles.front();
  EXPECT_EQ(t.on_canvas, (Rect{0, 0, 50, 50}));
  EXPECT_EQ(t.on_display, (Rect{0, 10, 50, 50}));
  // Every display pixel planned exactly once: the turned tiles tile the panel.
  long area = 0;
  for (const DisplayTile& d : layout.tiles) area += d.on_display.area();
  EXPECT_EQ(area, 100 * 60);
  // The report says how it hangs.
  EXPECT_NE(
      format_plan(layout).find("display 0: 100x60 turned 90 (60x100 on the canvas) at canvas 0,0"),
      std::string::npos)
      << format_plan(layout);
}

TEST(HangingWall, ErrorsNameTheFieldInOneLine) {
  EXPECT_EQ(
      hanging_error_of("[[display]]\nwidth = 100\nheight = 60\nx = 0\ny = 0\nrotation = 45\n" +
                       kHangingTail),
      "walls/h.toml:6: display[0].rotation: must be 0, 90, 180 or 270, got 45");
  EXPECT_EQ(
      hanging_error_of("[[display]]\nwidth = 100\nheight = 60\nx = 0\ny = 0\nrotation = 360\n" +
                       kHangingTail),
      "walls/h.toml:6: display[0].rotation: must be 0..270, got 360");
  EXPECT_EQ(
      hanging_error_of(
          "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 60\nflip = \"both\"\n" +
          kHangingTail),
      "walls/h.toml:6: display_grid.flip: must be one of none, horizontal, vertical, got \"both\"");
  // Projector overlap is limited by the turned size on the canvas (60 wide at 90).
  EXPECT_EQ(hanging_error_of("[display_grid]\ncolumns = 2\nrows = 1\nwidth = 100\nheight = 60\n"
                             "rotation = 90\nmullion_x = -60\n" +
                             kHangingTail),
            "walls/h.toml:7: display_grid.mullion_x: must be -59..4095, got -60");
}

}  // namespace
}  // namespace l2
