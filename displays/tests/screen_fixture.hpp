// Shared by the screen tests: a private Xvfb per test and recognisable display pictures.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "displays/xvfb_server.hpp"
#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2::testing {

// Starts Xvfb with a screen of the given size, or skips the test when Xvfb is not installed.
#define L2_START_XVFB(server, width, height)                                            \
  if (!::l2::testing::XvfbServer::installed()) GTEST_SKIP() << "Xvfb is not installed"; \
  auto server = std::make_unique<::l2::testing::XvfbServer>(width, height)

// Every pixel different from its neighbours and from other displays' pixels, so any shift,
// flip, filtering or mix-up between displays shows.
inline RgbImage distinct_picture(int display, int w, int h) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      image.set(x, y,
                {static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>(y * 5 + x * 3),
                 static_cast<std::uint8_t>(display * 60 + (x ^ y))});
    }
  }
  return image;
}

inline Wall grid_wall(int columns, int rows, int w, int h, int mullion) {
  Wall wall;
  for (int i = 0; i < columns * rows; ++i) {
    Display d;
    d.id = i;
    d.width = w;
    d.height = h;
    d.canvas_x = (i % columns) * (w + mullion);
    d.canvas_y = (i / columns) * (h + mullion);
    d.monitor = std::to_string(i);
    wall.displays.push_back(d);
  }
  wall.canvas_width = columns * (w + mullion) - mullion;
  wall.canvas_height = rows * (h + mullion) - mullion;
  return wall;
}

}  // namespace l2::testing
