// The strip headers of one pipeserver framebuffer for one frame parity (spec §4 rule 3), encoded
// once. Drawing them is then a six-byte copy per header, cheap enough to do row by row while the
// scan-out still has the row in the cache: drawn over the whole frame afterwards, every header
// missed the cache (one miss per scanline per tile): 0.06-0.12 ms against 0.25-0.40 ms for the
// scan-out itself (pipeserver_bench, default wall).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

class FrameHeaders {
 public:
  // Every COPY / SKIP / END header of `plan` with `frame_parity`.
  FrameHeaders(const PipeserverPlan& plan, bool frame_parity);

  // Writes the headers of scanline `y` (0 = top) into `row`, an RGB scanline of the plan's
  // framebuffer; touches only header pixels. Throws std::invalid_argument when y is outside the
  // framebuffer or `row` is shorter than a scanline.
  void draw_row(int y, std::span<std::uint8_t> row) const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Placed {
    std::uint32_t byte_offset;           // of the header's first pixel in its scanline
    std::array<std::uint8_t, 6> pixels;  // two RGB pixels
  };
  int width_ = 0, height_ = 0;
  std::vector<Placed> headers_;           // scanline by scanline, left to right
  std::vector<std::uint32_t> row_begin_;  // headers_ of scanline y: [row_begin_[y], [y + 1])
};

}  // namespace l2
