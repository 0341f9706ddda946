// Which desktop pixels each pipeserver is sent for a session's vnc windows (pure): the parts its
// tiles sample through the windows where the frame shows them.
#include "desktops/desktop_regions.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(DesktopRegions, EachTileGetsWhatItsPartOfTheWindowSamples) {
  // A 400x300 desktop 1:1 in a 100x80 window at canvas 150,50; tiles of 200x200.
  const std::vector<Rect> tiles{{0, 0, 200, 200}, {200, 0, 200, 200}, {0, 200, 200, 200}};
  const std::vector<DesktopWindow> windows{{3, SourceFit::OneToOne}};
  const std::vector<WindowPlace> shown{{0, {0, 0, 400, 400}}, {3, {150, 50, 100, 80}}};
  // The first tile holds the window's left 50 columns, the second its right 50; the third
  // none of it.
  EXPECT_EQ(desktop_regions(tiles, shown, windows, 400, 300),
            (std::vector<Rect>{{0, 0, 50, 80}, {50, 0, 50, 80}}));
  EXPECT_EQ(desktop_regions({tiles[2]}, shown, windows, 400, 300), std::vector<Rect>{});
  // A window of another desktop, or closed, asks for nothing.
  EXPECT_EQ(desktop_regions(tiles, {{0, {0, 0, 400, 400}}}, windows, 400, 300),
            std::vector<Rect>{});
}

TEST(DesktopRegions, AStretchedDesktopIsSentWhereItsPixelsAreSampled) {
  // A 400x300 desktop stretched on a 200x150 window at the canvas's origin (2 desktop pixels a
  // canvas pixel): window pixel x samples desktop pixel floor(2x + 1).
  const std::vector<DesktopWindow> windows{{0, SourceFit::Stretch}};
  const std::vector<WindowPlace> shown{{0, {0, 0, 200, 150}}};
  EXPECT_EQ(desktop_regions({{0, 0, 100, 1000}, {100, 0, 100, 1000}}, shown, windows, 400, 300),
            (std::vector<Rect>{{1, 1, 199, 299}, {201, 1, 199, 299}}));
  // Two windows of the same desktop overlapping one tile: each its own region, none twice.
  const std::vector<DesktopWindow> two{{0, SourceFit::OneToOne}, {1, SourceFit::OneToOne}};
  EXPECT_EQ(desktop_regions({{0, 0, 500, 500}}, {{0, {0, 0, 50, 50}}, {1, {10, 10, 50, 50}}}, two,
                            400, 300),
            (std::vector<Rect>{{0, 0, 50, 50}}));
}

}  // namespace
}  // namespace l2
