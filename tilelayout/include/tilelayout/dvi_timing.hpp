// The DVI link a pipeserver's framebuffer goes out on: the pixel clock it needs at a refresh
// rate, and whether a single link (165 MHz) or a dual link (330 MHz) carries it.
//
// The blanking is VESA CVT's reduced blanking, version 1 (CVT 1.2 §5.4): 160 pixels a line;
// at least 460 us of vertical blanking in whole lines, and no fewer lines than the front porch
// (3), the sync (4 to 10 lines by aspect ratio) and the back porch (6); the clock rounded down
// to a multiple of 0.25 MHz. One deviation: CVT rounds a width down to 8-pixel character cells,
// here it is rounded up, since every pixel of a framebuffer must go over the link.
#pragma once

namespace l2 {

inline constexpr double kSingleLinkDviMhz = 165.0;
inline constexpr double kDualLinkDviMhz = 330.0;

struct DviTiming {
  int h_total = 0, v_total = 0;  // pixels a line and lines a frame, blanking included
  double pixel_clock_mhz = 0;
  // 1: a single link carries it, 2: a dual link does, 0: not even a dual link.
  int links() const;
};

// width, height >= 1, refresh_hz 1..1000 (as a wall file allows).
DviTiming dvi_timing(int width, int height, int refresh_hz);

// The highest whole refresh rate, 1..1000 Hz, whose pixel clock a link of `link_mhz` carries at
// width x height (0 when not even 1 Hz does): what the emulator refreshes at, at most.
int max_refresh_hz(int width, int height, double link_mhz);

}  // namespace l2
