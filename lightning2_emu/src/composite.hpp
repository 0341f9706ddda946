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

// One pixel: the colour and rank replaced where `write`. Masks, not branches: the loops
// compile to straight-line code.
inline void select(std::uint8_t* __restrict dst, std::uint32_t& __restrict rank,
                   const std::uint8_t* __restrict src, std::uint32_t new_rank, bool write) {
  const std::uint32_t m = 0u - static_cast<std::uint32_t>(write);
  const auto m8 = static_cast<std::uint8_t>(m);
  rank = (new_rank & m) | (rank & ~m);
  dst[0] = static_cast<std::uint8_t>((src[0] & m8) | (dst[0] & ~m8));
  dst[1] = static_cast<std::uint8_t>((src[1] & m8) | (dst[1] & ~m8));
  dst[2] = static_cast<std::uint8_t>((src[2] & m8) | (dst[2] & ~m8));
}

// COPY (kKeyed false) or KEY pixels of input `input`: n colour pixels bpp bytes apart.
template <bool kKeyed, int kBpp>
void overlay(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
             const std::uint8_t* __restrict src, int n, int bpp, std::uint32_t key, int input) {
  const int step = kBpp ? kBpp : bpp;
  const std::uint32_t r = opaque_rank(input);
  for (int i = 0; i < n; ++i) {
    const std::uint8_t* s = src + i * step;
    const bool write = (r <= rank[i]) & (!kKeyed | (rgb_at(s) != key));
    select(dst + 3 * i, rank[i], s, r, write);
  }
}

// DEPTH pixels of input `input`: n colour pixels, their depths at `depth`.
template <int kBpp>
void depth(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
           const std::uint8_t* __restrict src, const std::uint8_t* __restrict depth, int n, int bpp,
           int input) {
  const int step = kBpp ? kBpp : bpp;
  const std::uint32_t tag = static_cast<std::uint32_t>(input);
  for (int i = 0; i < n; ++i) {
    const std::uint32_t d = rgb_at(depth + i * step);
    const std::uint32_t r = std::min((d + 1) << 8 | tag, kFar - 1);
    select(dst + 3 * i, rank[i], src + i * step, r, (d < kFarDepth) & (r < rank[i]));
  }
}

// One display row after the frame's strips: background where nothing was written, every rank
// back to kFar for the next frame. Returns the pixels written.
inline int settle(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank, int n,
                  std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  int written = 0;
  for (int i = 0; i < n; ++i) {
    const bool empty = rank[i] == kFar;
    written += static_cast<int>(!empty);
    const std::uint8_t bg[3] = {r, g, b};
    select(dst + 3 * i, rank[i], bg, kFar, empty);
    rank[i] = kFar;
  }
  return written;
}

}  // namespace l2::composite
