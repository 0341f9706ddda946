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

#include <algorithm>
#include <cstdint>

namespace l2::composite {

inline constexpr std::uint32_t kFar = 0xFFFFFFFF;
inline constexpr std::uint32_t kFarDepth = 0xFFFFFF;

inline std::uint32_t opaque_rank(int input) {
  return 255u - static_cast<std::uint32_t>(input);
}

inline std::uint32_t rgb_at(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
}

// One pixel: the colour and rank replaced where `write`. Branch-free so the loops vectorise.
inline void select(std::uint8_t* dst, std::uint32_t& rank, const std::uint8_t* src,
                   std::uint32_t new_rank, bool write) {
  rank = write ? new_rank : rank;
  dst[0] = write ? src[0] : dst[0];
  dst[1] = write ? src[1] : dst[1];
  dst[2] = write ? src[2] : dst[2];
}

// COPY (kKeyed false) or KEY pixels of input `input`: n colour pixels bpp bytes apart.
template <bool kKeyed, int kBpp>
void overlay(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n, int bpp,
             std::uint32_t key, int input) {
  const int step = kBpp ? kBpp : bpp;
  const std::uint32_t r = opaque_rank(input);
  for (int i = 0; i < n; ++i) {
    const std::uint8_t* s = src + i * step;
    const bool write = r <= rank[i] && (!kKeyed || rgb_at(s) != key);
    select(dst + 3 * i, rank[i], s, r, write);
  }
}

// DEPTH pixels of input `input`: n colour pixels, their depths at `depth`.
template <int kBpp>
void depth(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
           const std::uint8_t* depth, int n, int bpp, int input) {
  const int step = kBpp ? kBpp : bpp;
  const std::uint32_t tag = static_cast<std::uint32_t>(input);
  for (int i = 0; i < n; ++i) {
    const std::uint32_t d = rgb_at(depth + i * step);
    const std::uint32_t r = std::min((d + 1) << 8 | tag, kFar - 1);
    select(dst + 3 * i, rank[i], src + i * step, r, d < kFarDepth && r < rank[i]);
  }
}

// One display row after the frame's strips: background where nothing was written, every rank
// back to kFar for the next frame. Returns the pixels written.
inline int settle(std::uint8_t* dst, std::uint32_t* rank, int n, std::uint8_t r, std::uint8_t g,
                  std::uint8_t b) {
  int written = 0;
  for (int i = 0; i < n; ++i) {
    const bool empty = rank[i] == kFar;
    written += empty ? 0 : 1;
    dst[3 * i] = empty ? r : dst[3 * i];
    dst[3 * i + 1] = empty ? g : dst[3 * i + 1];
    dst[3 * i + 2] = empty ? b : dst[3 * i + 2];
    rank[i] = kFar;
  }
  return written;
}

}  // namespace l2::composite
