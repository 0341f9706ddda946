// The DVI pixel clock of a framebuffer at a refresh rate, against the CVT reduced-blanking
// timings VESA publishes in its Display Monitor Timing standard (DMT 1.0 r13), and two worked
// by hand from CVT 1.2's formula.
#include "tilelayout/dvi_timing.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

struct Published {
  int width, height, hz;
  int h_total, v_total;
  double mhz;
  int links;
};

class DviTimingOf : public ::testing::TestWithParam<Published> {};

TEST_P(DviTimingOf, MatchesVesa) {
  const Published& p = GetParam();
  const DviTiming t = dvi_timing(p.width, p.height, p.hz);
  EXPECT_EQ(t.h_total, p.h_total);
  EXPECT_EQ(t.v_total, p.v_total);
  EXPECT_DOUBLE_EQ(t.pixel_clock_mhz, p.mhz);
  EXPECT_EQ(t.links(), p.links);
}

INSTANTIATE_TEST_SUITE_P(Dmt, DviTimingOf,
                         ::testing::Values(Published{1280, 768, 60, 1440, 790, 68.25, 1},
                                           Published{1280, 800, 60, 1440, 823, 71.00, 1},
                                           Published{1400, 1050, 60, 1560, 1080, 101.00, 1},
                                           Published{1680, 1050, 60, 1840, 1080, 119.00, 1},
                                           Published{1920, 1200, 60, 2080, 1235, 154.00, 1},
                                           Published{1920, 1200, 120, 2080, 1271, 317.00, 2},
                                           Published{2560, 1600, 60, 2720, 1646, 268.50, 2},
                                           Published{2560, 1600, 120, 2720, 1694, 552.75, 0}));

TEST(DviTiming, AShortFrameGetsTheLeastBlankingCvtAllows) {
  // 640x480 at 30 Hz: 460 us are 7 lines, fewer than porches and sync (3 + 4 + 6).
  const DviTiming t = dvi_timing(640, 480, 30);
  EXPECT_EQ(t.v_total, 493);
  EXPECT_EQ(t.h_total, 800);
  EXPECT_DOUBLE_EQ(t.pixel_clock_mhz, 11.75);  // 30 x 493 x 800 = 11.832 MHz, rounded down
}

TEST(DviTiming, AWidthOffTheCharacterCellsIsRoundedUp) {
  // 964 pixels go out as 968 (121 cells of 8), plus 160 of blanking.
  const DviTiming t = dvi_timing(964, 2560, 41);
  EXPECT_EQ(t.h_total, 1128);
  EXPECT_EQ(t.v_total, 2610);
  EXPECT_DOUBLE_EQ(t.pixel_clock_mhz, 120.50);  // 41 x 2610 x 1128 = 120.706 MHz
}

TEST(DviTiming, TheFastestRefreshALinkCarries) {
  // 800x600 by hand: 960 pixels a line; at 453 Hz a frame is 2207.5 us, a line (2207.5 - 460) /
  // 600 = 2.9125 us, so 158 blanking lines and 758 in all: 453 x 758 x 960 = 329.64 MHz, 329.5
  // after rounding, within a dual link. At 454 Hz 159 lines: 454 x 759 x 960 = 330.8 MHz.
  EXPECT_EQ(max_refresh_hz(800, 600, kDualLinkDviMhz), 453);
  EXPECT_LE(dvi_timing(800, 600, 453).pixel_clock_mhz, kDualLinkDviMhz);
  EXPECT_GT(dvi_timing(800, 600, 454).pixel_clock_mhz, kDualLinkDviMhz);
  // Within the rates a run takes, a small frame fits at any of them; nothing fits a 0 MHz link.
  EXPECT_EQ(max_refresh_hz(64, 48, kDualLinkDviMhz), 1000);
  EXPECT_EQ(max_refresh_hz(800, 600, 0.0), 0);
}

}  // namespace
}  // namespace l2
