// Compositing (spec §7) on displays that get KEY or DEPTH strips, in a form whose result does not
// depend on the order strips are applied in, so inputs that deliver their frames at different
// refreshes composite as if every strip of the frame had been applied in pixel-bus order.
//
// Applied in bus order, §7's rules leave a pixel with the colour of the last opaque (COPY or
// non-transparent KEY) pixel written to it if there is one (no DEPTH can cover depth 0, a later
// opaque pixel replaces it); otherwise with the DEPTH pixel of least depth, of equal depths the
// one earliest on the bus; otherwise the background. So each pixel keeps a 32-bit rank beside its
// colour, and a strip pixel is written where its rank is below the pixel's:
//   opaque from input i           255 - i                 a later input ranks lower
//   DEPTH D (< FFFFFF) from i     (D + 1) << 8 | i        below kFar; least depth, then input
//   nothing written yet           kFar
// Within one input, later strips on the bus replace opaque pixels of equal rank (<=) and do not
// replace DEPTH pixels of equal rank (<): scan order does the rest. The one rank that does not
// fit, depth FFFFFE from input 255 of a 64-row mesh, is taken as input 254's.
#pragma once

#include <cstdint>

namespace l2::composite {

inline constexpr std::uint32_t kFar = 0xFFFFFFFF;
inline constexpr std::uint32_t kFarDepth = 0xFFFFFF;

inline std::uint32_t opaque_rank(int input) {
  return 255u - static_cast<std::uint32_t>(input);
}

// The per-pixel loops, one display row span a call (composite.cpp). `bpp`: bytes a strip pixel
// (3 RGB, 4 RGBA; wider pixels take a loop that is not vectorised).
// COPY (keyed false) or KEY pixels of input `input`: n colour pixels.
void overlay(bool keyed, std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n,
             int bpp, std::uint32_t key, int input);
// DEPTH pixels of input `input`: n colour pixels, their depths at `depth`.
void depth(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
           const std::uint8_t* depth, int n, int bpp, int input);
// One display row after the frame's strips: background where nothing was written, every rank
// back to kFar for the next frame. Returns the pixels written.
int settle(std::uint8_t* dst, std::uint32_t* rank, int n, std::uint8_t r, std::uint8_t g,
           std::uint8_t b);

}  // namespace l2::composite
