#include "displays/wall_view.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace l2 {
namespace {

Wall two_by_two(int w, int h, int mullion) {
  Wall wall;
  for (int i = 0; i < 4; ++i) {
    Display d;
    d.id = i;
    d.width = w;
    d.height = h;
    d.canvas_x = (i % 2) * (w + mullion);
    d.canvas_y = (i / 2) * (h + mullion);
    wall.displays.push_back(d);
  }
  return wall;
}

TEST(WallView, FitsAtNativeSizeWithMullionsAndOverlayBelow) {
  const WallView v = fit_wall(two_by_two(320, 240, 10), 1000, 1000, 22);
  EXPECT_EQ(v.scale, 1.0);
  EXPECT_EQ(v.width, 650);
  EXPECT_EQ(v.height, 490 + 22);
  EXPECT_EQ(v.display_rects[0], (Rect{0, 0, 320, 240}));
  EXPECT_EQ(v.display_rects[1], (Rect{330, 0, 320, 240}));
  EXPECT_EQ(v.display_rects[3], (Rect{330, 250, 320, 240}));
  EXPECT_EQ(v.overlay, (Rect{0, 490, 650, 22}));
}

TEST(WallView, ScalesDownToTheTighterSideAndKeepsMullions) {
  // 650 x 490 wall into 325 wide: half size.
  const WallView v = fit_wall(two_by_two(320, 240, 10), 325, 1000, 0);
  EXPECT_DOUBLE_EQ(v.scale, 0.5);
  EXPECT_EQ(v.display_rects[0], (Rect{0, 0, 160, 120}));
  EXPECT_EQ(v.display_rects[1], (Rect{165, 0, 160, 120}));
  EXPECT_EQ(v.display_rects[2], (Rect{0, 125, 160, 120}));
  EXPECT_EQ(v.width, 325);
  EXPECT_EQ(v.height, 245);
}

TEST(WallView, WallOffTheCanvasOriginIsShownFromItsFirstDisplay) {
  Wall wall = two_by_two(100, 50, 0);
  for (Display& d : wall.displays) d.canvas_x += 40, d.canvas_y += 30;
  EXPECT_EQ(wall_extent(wall), (Rect{40, 30, 200, 100}));
  EXPECT_EQ(fit_wall(wall, 500, 500, 0).display_rects[0], (Rect{0, 0, 100, 50}));
}

TEST(WallView, RefusesAnEmptyWallOrNoRoom) {
  EXPECT_THROW(fit_wall(Wall{}, 100, 100, 0), std::invalid_argument);
  EXPECT_THROW(fit_wall(two_by_two(10, 10, 0), 100, 20, 20), std::invalid_argument);
}

TEST(WallView, FitDisplayCentresAtNativeSizeOrScalesKeepingAspect) {
  EXPECT_EQ(fit_display(640, 480, 1600, 1200), (Rect{480, 360, 640, 480}));
  EXPECT_EQ(fit_display(1600, 1200, 1600, 1200), (Rect{0, 0, 1600, 1200}));
  EXPECT_EQ(fit_display(3200, 1200, 1600, 1200), (Rect{0, 300, 1600, 600}));
}

}  // namespace
}  // namespace l2
