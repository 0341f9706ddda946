#include "displays/wall_window.hpp"

#include <gtest/gtest.h>

#include "displays/colours.hpp"
#include "screen_fixture.hpp"

namespace l2 {
namespace {

using testing::distinct_picture;
using testing::grid_wall;

std::vector<RgbImage> pictures(const Wall& wall) {
  std::vector<RgbImage> images;
  for (const Display& d : wall.displays)
    images.push_back(distinct_picture(d.id, d.width, d.height));
  return images;
}

TEST(WallWindow, ShowsEveryDisplayPixelForPixelAtNativeSize) {
  L2_START_XVFB(xvfb, 1024, 768);
  const Wall wall = grid_wall(2, 2, 200, 150, 12);
  const std::vector<RgbImage> images = pictures(wall);
  WallWindow window(wall, {.vsync = false});
  ASSERT_EQ(window.view().scale, 1.0);
  for (int frame = 0; frame < 5; ++frame) {
    window.present({frame, 60.0, 1, false}, images);
    EXPECT_EQ(window.poll_events(), UserAction::None);
  }
  const std::vector<RgbImage> shown = window.read_back();
  ASSERT_EQ(shown.size(), 4u);
  for (std::size_t d = 0; d < 4; ++d) EXPECT_TRUE(shown[d] == images[d]) << "display " << d;
}

TEST(WallWindow, MullionsAreDarkBarsAndTheOverlayHasText) {
  L2_START_XVFB(xvfb, 1024, 768);
  const Wall wall = grid_wall(2, 1, 100, 80, 10);
  WallWindow window(wall, {.vsync = false});
  window.present({7, 59.8, 1, false}, pictures(wall));
  const std::vector<RgbImage> windows = window.read_back_windows();
  ASSERT_EQ(windows.size(), 1u);
  const RgbImage& w = windows[0];
  ASSERT_EQ(w.width(), 210);
  ASSERT_EQ(w.height(), 80 + WallWindow::kOverlayHeight);
  for (int y = 0; y < 80; ++y) {
    for (int x = 100; x < 110; ++x) ASSERT_EQ(w.at(x, y), kMullionColour) << x << "," << y;
  }
  int ink = 0;
  for (int y = 80; y < w.height(); ++y) {
    for (int x = 0; x < w.width(); ++x) ink += w.at(x, y) == kOverlayTextColour;
  }
  EXPECT_GT(ink, 50);
}

TEST(WallWindow, WallLargerThanTheScreenIsScaledToFit) {
  L2_START_XVFB(xvfb, 640, 480);
  const Wall wall = grid_wall(2, 1, 640, 400, 20);
  WallWindow window(wall, {.vsync = false});
  EXPECT_LT(window.view().scale, 1.0);
  EXPECT_LE(window.view().width, 640);
  window.present({0, 0.0, 1, false}, pictures(wall));
  const std::vector<RgbImage> shown = window.read_back();
  EXPECT_EQ(shown[0].width(), window.view().display_rects[0].w);
  EXPECT_LT(shown[0].width(), 640);
}

TEST(WallWindow, RefusesTheWrongNumberOfImages) {
  L2_START_XVFB(xvfb, 640, 480);
  const Wall wall = grid_wall(2, 1, 64, 48, 4);
  WallWindow window(wall, {.vsync = false});
  EXPECT_THROW(window.present({}, {RgbImage(64, 48)}), std::invalid_argument);
}

}  // namespace
}  // namespace l2
