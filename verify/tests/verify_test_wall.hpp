// The verifier tests' wall: two 64x32 displays 16 pixels apart, four 32x32 tiles dealt
// round-robin to two pipeservers, so each framebuffer holds one row of two tiles:
//   pipeserver 0: tile 0 (display 0 at 0,0) at fb x 2, tile 2 (display 1 at 0,0) at fb x 36
//   pipeserver 1: tile 1 (display 0 at 32,0) at fb x 2, tile 3 (display 1 at 32,0) at fb x 36
// Frames are those tilelayout --scanout writes (test_frame), corrupted header by header.
#pragma once

#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::verify_test {

inline constexpr const char* kWallToml = R"(name = "verifier test wall"
[display_grid]
columns = 2
rows = 1
width = 64
height = 32
mullion_x = 16
[tiling]
kind = "list"
tiles = [[0, 0, 32, 32], [32, 0, 32, 32], [80, 0, 32, 32], [112, 0, 32, 32]]
[pipeservers]
count = 2
framebuffer_width = 80
framebuffer_height = 64
)";

inline TileLayout test_layout() {
  return plan_layout(parse_wall(kWallToml, ""));
}

inline std::vector<RgbImage> scanned_out(const TileLayout& layout) {
  std::vector<RgbImage> frames;
  for (const PipeserverPlan& s : layout.pipeservers) frames.push_back(test_frame(s, false));
  return frames;
}

// Redraws the header before the strip starting at column `strip_x` of scanline `y`.
inline void set_header(RgbImage& frame, int strip_x, int y, const StripHeader& header) {
  write_header_pixels(encode(header), frame.row(y).data() + (strip_x - kHeaderPixels) * 3, 3);
}

// The header drawn before the strip starting at column `strip_x` of scanline `y`.
inline StripHeader header_at(const RgbImage& frame, int strip_x, int y) {
  const std::uint8_t* p = frame.row(y).data() + (strip_x - kHeaderPixels) * 3;
  return *decode(header_value(p, p + 3));
}

}  // namespace l2::verify_test
