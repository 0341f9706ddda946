#include "displays/monitor_wall.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "displays/display_error.hpp"
#include "screen_fixture.hpp"

namespace l2 {
namespace {

using testing::distinct_picture;
using testing::grid_wall;
using ::testing::HasSubstr;

TEST(MonitorWall, FewerMonitorsThanDisplaysIsRefusedListingTheOneXvfbHas) {
  L2_START_XVFB(xvfb, 800, 600);
  Wall wall = grid_wall(2, 1, 320, 240, 0);
  wall.name = "pair";
  try {
    MonitorWall shown(wall, {.vsync = false});
    FAIL() << "opened 2 fullscreen displays on one monitor";
  } catch (const DisplayError& e) {
    EXPECT_THAT(e.what(), HasSubstr("wall 'pair': --show monitors needs one monitor per display: "
                                    "2 displays, but GLFW sees 1 monitor: [0] \""));
    EXPECT_THAT(e.what(), HasSubstr("800x600 at (0,0)"));
  }
}

TEST(MonitorWall, OneDisplayFullscreenOnItsMonitorIsPixelExact) {
  L2_START_XVFB(xvfb, 800, 600);
  Wall wall = grid_wall(1, 1, 320, 240, 0);
  const std::vector<RgbImage> images = {distinct_picture(0, 320, 240)};
  MonitorWall shown(wall, {.vsync = false});
  for (int frame = 0; frame < 3; ++frame) shown.present({frame, 0.0, 1, false}, images);
  const std::vector<RgbImage> back = shown.read_back();
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(back[0] == images[0]);
  // Fullscreen: the window covers the monitor, the display centred in black.
  const std::vector<RgbImage> windows = shown.read_back_windows();
  ASSERT_EQ(windows[0].width(), 800);
  ASSERT_EQ(windows[0].height(), 600);
  EXPECT_EQ(windows[0].at(0, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(windows[0].at(240, 180), images[0].at(0, 0));
}

TEST(MonitorWall, WithoutAScreenTheErrorSaysSo) {
  const char* saved = std::getenv("DISPLAY");
  const std::string keep = saved ? saved : "";
  setenv("DISPLAY", ":4093", 1);  // no server there
  try {
    MonitorWall shown(grid_wall(1, 1, 32, 32, 0), {});
    FAIL() << "opened a window without an X server";
  } catch (const DisplayError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot open the screen"));
    EXPECT_THAT(e.what(), HasSubstr("DISPLAY=:4093"));
  }
  if (saved)
    setenv("DISPLAY", keep.c_str(), 1);
  else
    unsetenv("DISPLAY");
}

}  // namespace
}  // namespace l2
