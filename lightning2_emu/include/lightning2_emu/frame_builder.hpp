// Scanned-out frames built by hand for tests and the benchmark, independent of the router:
// headers are written with the strip-header codec and strip pixels from a known pattern, so the
// expected display contents are known without routing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/extension_word.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2::testing {

// A colour that differs for (nearly) every display, column and row: a strip landing anywhere
// else than where it belongs shows up as a wrong colour.
Rgb pattern(int display, int x, int y);

// One frame under construction; starts black (every scanline reads as END).
class FrameBuilder {
 public:
  FrameBuilder(int width, int height) : image_(width, height) {}
  RgbImage& image() { return image_; }
  const RgbImage& image() const { return image_; }

  void raw_header(int x, int y, std::uint64_t value);
  void header(int x, int y, const StripHeader& h) { raw_header(x, y, encode(h)); }
  // A COPY header at x followed by `width` pixels pattern(display, dx + k, dy); returns the
  // column after the strip.
  int copy(int x, int y, int display, int dx, int dy, int width, bool parity = false);
  // The same with one colour.
  int copy_fill(int x, int y, int display, int dx, int dy, int width, Rgb colour,
                bool parity = false);
  int skip(int x, int y, int width, bool parity = false);
  // An EXT header (frame 0) and its extension word at x; returns the payload's column.
  int ext(int x, int y, int display, int dx, int dy, int width, const Extension& e);
  // A DEPTH strip (frame 0) at x: the colours, then their depths as pixels D = R<<16 | G<<8 |
  // B; returns the next header's column.
  int depth(int x, int y, int display, int dx, int dy, const std::vector<Rgb>& colours,
            const std::vector<std::uint32_t>& depths);

 private:
  RgbImage image_;
};

// A rectangle of one display, as a pipeserver renders it.
struct Tile {
  int display = 0, dx = 0, dy = 0, w = 0, h = 0;
};

// Packs tiles per spec §4 (left to right, new row when the next gap + tile would pass the
// width, rows as tall as their tallest tile, SKIP below short tiles, END after the last tile)
// with pixels pattern(display, x, y). Returns false when the tiles do not fit.
bool pack_frame(std::span<const Tile> tiles, bool parity, RgbImage& frame);

// A display of `width` x `height` pixels filled with pattern(display, x, y).
RgbImage pattern_image(int display, int width, int height);

}  // namespace l2::testing
