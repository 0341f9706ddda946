// Turning pictures between a panel's raster and its canvas rectangle: every panel pixel against
// the canvas pixel the wall file's documented formulas name (docs/wall-file.md), written out
// here per rotation and flip, not asked of the code under test.
#include <gtest/gtest.h>

#include "image/turn.hpp"

namespace l2 {
namespace {

// A canvas rectangle whose every pixel says where it is.
RgbImage positions(int w, int h) {
  RgbImage img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.set(x, y, Rgb{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7});
  return img;
}

struct Expected {
  int u, v;
};

// The documented mapping: panel pixel (x, y) of a panel of native W x H shows canvas offset (u, v)
// of its canvas rectangle, which is cw wide and ch tall. Flip first, in panel coordinates.
Expected documented(int rotation, Flip flip, int W, int H, int x, int y) {
  if (flip == Flip::Horizontal) x = W - 1 - x;
  if (flip == Flip::Vertical) y = H - 1 - y;
  const int cw = rotation % 180 ? H : W, ch = rotation % 180 ? W : H;
  switch (rotation) {
    case 90:
      return {cw - 1 - y, x};
    case 180:
      return {cw - 1 - x, ch - 1 - y};
    case 270:
      return {y, ch - 1 - x};
    default:
      return {x, y};
  }
}

class TurnEach : public ::testing::TestWithParam<std::tuple<int, Flip>> {};

TEST_P(TurnEach, EveryPanelPixelShowsTheDocumentedCanvasPixel) {
  const auto [rotation, flip] = GetParam();
  const int W = 7, H = 4;  // native: landscape, odd and even sides
  const int cw = rotation % 180 ? H : W, ch = rotation % 180 ? W : H;
  const RgbImage canvas = positions(cw, ch);
  const Orientation o{rotation, flip};
  const RgbImage panel = to_panel(canvas, o);
  ASSERT_EQ(panel.width(), W);
  ASSERT_EQ(panel.height(), H);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const Expected e = documented(rotation, flip, W, H, x, y);
      EXPECT_EQ(panel.at(x, y),
                (Rgb{static_cast<std::uint8_t>(e.u), static_cast<std::uint8_t>(e.v), 7}))
          << "panel pixel " << x << "," << y;
      const PanelMap m = panel_map(o, W, H, 100, 200);
      EXPECT_EQ(m.u(x, y), 100 + e.u);
      EXPECT_EQ(m.v(x, y), 200 + e.v);
      EXPECT_EQ(m.x_of(m.u(x, y), m.v(x, y)), x);
      EXPECT_EQ(m.y_of(m.u(x, y), m.v(x, y)), y);
    }
  }
  EXPECT_EQ(to_canvas(panel, o), canvas);  // and back, as a window shows the panel hanging
}

INSTANTIATE_TEST_SUITE_P(AllFour, TurnEach,
                         ::testing::Combine(::testing::Values(0, 90, 180, 270),
                                            ::testing::Values(Flip::None, Flip::Horizontal,
                                                              Flip::Vertical)));

TEST(Turn, NinetyIsTheIssuesExample) {
  // rotation = 90: display pixel (x, y) shows canvas pixel (x0 + w - 1 - y, y0 + x), w the width
  // on the canvas. A 3x2 panel covers 2x3; its pixel (0, 0) shows the canvas's top-right.
  const PanelMap m = panel_map({90, Flip::None}, 3, 2, 10, 20);
  EXPECT_EQ(m.u(0, 0), 11);
  EXPECT_EQ(m.v(0, 0), 20);
  EXPECT_EQ(m.u(2, 1), 10);
  EXPECT_EQ(m.v(2, 1), 22);
}

}  // namespace
}  // namespace l2
