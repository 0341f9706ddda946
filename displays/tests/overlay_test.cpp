#include "displays/overlay.hpp"

#include <gtest/gtest.h>

#include "displays/colours.hpp"

namespace l2 {
namespace {

TEST(Overlay, LineShowsFrameFpsAndLatency) {
  EXPECT_EQ(overlay_line({12, 59.84, 1, false}), "frame 12  59.8 fps  latency 1 frame");
  EXPECT_EQ(overlay_line({3, 30.0, 2, true}), "frame 3  30.0 fps  latency 2 frames  paused");
  EXPECT_EQ(overlay_line({0, 0.0, std::nullopt, false}), "frame 0  0.0 fps  latency n/a");
}

TEST(Overlay, RendersTextOnTheMullionColour) {
  const RgbImage bar = render_overlay("frame 1", 200, 22);
  EXPECT_EQ(bar.width(), 200);
  EXPECT_EQ(bar.height(), 22);
  // Every pixel the mullion colour, the text's, or (its edges) a blend of the two.
  const auto between = [](int c, int a, int b) {
    return c >= std::min(a, b) && c <= std::max(a, b);
  };
  int ink = 0;
  for (int y = 0; y < bar.height(); ++y) {
    for (int x = 0; x < bar.width(); ++x) {
      const Rgb c = bar.at(x, y);
      if (c == kOverlayTextColour) ++ink;
      EXPECT_TRUE(between(c.r, kMullionColour.r, kOverlayTextColour.r) &&
                  between(c.g, kMullionColour.g, kOverlayTextColour.g) &&
                  between(c.b, kMullionColour.b, kOverlayTextColour.b))
          << x << "," << y;
    }
  }
  EXPECT_GT(ink, 0);
  EXPECT_EQ(bar.at(199, 0), kMullionColour);
}

TEST(FpsMeter, AveragesOverItsWindow) {
  using namespace std::chrono_literals;
  FpsMeter meter(5);
  const auto t0 = FpsMeter::Clock::time_point{};
  EXPECT_EQ(meter.fps(), 0.0);
  meter.tick(t0);
  EXPECT_EQ(meter.fps(), 0.0);
  for (int i = 1; i <= 4; ++i) meter.tick(t0 + i * 20ms);
  EXPECT_NEAR(meter.fps(), 50.0, 1e-9);
  // The window forgets the slow start: the last 5 ticks are 10 ms apart.
  for (int i = 1; i <= 4; ++i) meter.tick(t0 + 80ms + i * 10ms);
  EXPECT_NEAR(meter.fps(), 100.0, 1e-9);
}

}  // namespace
}  // namespace l2
