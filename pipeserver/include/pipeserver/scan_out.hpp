// Scan-out (spec §1): the GL framebuffer (RGBA, rows bottom to top) becomes the 24-bit RGB frame
// a DVI link carries (rows top to bottom, alpha dropped). A hot path: one pass per row, no
// per-pixel calls; the destination is the caller's: the live pipeserver's is its DVI link's back
// frame in shared memory.
#pragma once

#include <cstdint>
#include <span>

#include "tilelayout/frame_headers.hpp"

namespace l2 {

// One row: `width` RGBA pixels to RGB (SSSE3 where the CPU has it).
void rgba_to_rgb_row(const std::uint8_t* rgba, std::uint8_t* rgb, int width);

// Converts a w x h RGBA bottom-up image into w x h RGB top-down in `dst_rgb` (w*h*3 bytes).
// Throws std::invalid_argument when dst_rgb is too small.
void scan_out(const std::uint8_t* rgba, int width, int height, std::span<std::uint8_t> dst_rgb);

// The same, and draws the strip headers into each scanline right after converting it, while it
// is still in the cache (drawn afterwards over the whole frame, each header missed the cache).
// Throws std::invalid_argument also when `headers` are for another framebuffer size.
void scan_out(const std::uint8_t* rgba, int width, int height, std::span<std::uint8_t> dst_rgb,
              const FrameHeaders& headers);

}  // namespace l2
