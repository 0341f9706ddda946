// Test helper: the strip header whose two RGB pixels start at (x, y) of a scanned-out frame.
#pragma once

#include <gtest/gtest.h>

#include "image/rgb_image.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2::test {

// A check-bit failure is a test failure; the header returned then is a default one.
inline StripHeader header_at(const RgbImage& fb, int x, int y) {
  const auto* p = fb.row(y).data() + static_cast<std::size_t>(x) * 3;
  const auto h = decode(header_value(p, p + 3));
  EXPECT_TRUE(h.has_value()) << "no valid header at " << x << "," << y;
  return h.value_or(StripHeader{});
}

}  // namespace l2::test
