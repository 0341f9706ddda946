// The compositing loops of composite.hpp. Where the machine has AVX2, composite_simd.cpp does
// all but the last few pixels of a span, and these plain loops the rest. Each is a compare and a
// select per pixel with no branch, over a row span with the pixel size fixed at compile time, so
// that GCC vectorises it. Three-byte pixels need byte shuffles to be taken apart 16 at a time,
// which SSE2 (the x86-64 baseline) lacks: each loop is also compiled for AVX2 and the one for the
// machine is chosen at load time (target_clones). This file is compiled with -O3 (CMakeLists.txt):
// at -O2 GCC 12's vectoriser takes on only loops it costs as very cheap, which these are not.
#include "composite.hpp"

#include "composite_simd.hpp"

namespace l2::composite {

namespace {

// Not under ThreadSanitizer: the clones' resolver runs while the program is being loaded, before
// TSan's runtime is set up, and the instrumented resolver crashed every test at start.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define L2_COMPOSITE_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define L2_COMPOSITE_CLONES
#endif

inline std::uint32_t rgb_at(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
}

// Pixel i's colour replaced where `write`, by masks, not branches.
[[gnu::always_inline]] inline void select_colour(std::uint8_t* __restrict dst, int i,
                                                 const std::uint8_t* __restrict src, bool write) {
  const auto m8 = static_cast<std::uint8_t>(write ? 0xFF : 0);
  for (int c = 0; c < 3; ++c) {
    dst[3 * i + c] = static_cast<std::uint8_t>((src[c] & m8) | (dst[3 * i + c] & ~m8));
  }
}

// Pixel i: colour and rank replaced where `write`.
[[gnu::always_inline]] inline void select(std::uint8_t* __restrict dst,
                                          std::uint32_t* __restrict rank, int i,
                                          const std::uint8_t* __restrict src,
                                          std::uint32_t new_rank, bool write) {
  const std::uint32_t m = write ? ~0u : 0u;
  rank[i] = (new_rank & m) | (rank[i] & ~m);
  select_colour(dst, i, src, write);
}

// Pixels a span is taken in at a time: its byte masks stay in the first-level cache.
constexpr int kChunk = 64;

// n strip pixels onto a row span, pixel i written where rule(i, rank[i], new_rank) says, with
// the rank new_rank. RGB pixels go in two passes a chunk: the ranks and a mask a colour byte,
// then the colour bytes blended as bytes, so that the colours are not taken apart into R, G
// and B lanes and put together again (most of the shuffles of a one-pass loop).
template <int kBpp, class Rule>
[[gnu::always_inline]] inline void apply_span(std::uint8_t* __restrict dst,
                                              std::uint32_t* __restrict rank,
                                              const std::uint8_t* __restrict src, int n, int bpp,
                                              Rule rule) {
  if constexpr (kBpp != 3) {
    const int step = kBpp ? kBpp : bpp;
    for (int i = 0; i < n; ++i) {
      std::uint32_t r;
      const bool write = rule(i, rank[i], r);
      select(dst, rank, i, src + i * step, r, write);
    }
  } else {
    for (int at = 0; at < n; at += kChunk) {
      const int len = n - at < kChunk ? n - at : kChunk;
      std::uint8_t mask[3 * kChunk];
      std::uint32_t* __restrict rk = rank + at;
      for (int i = 0; i < len; ++i) {
        std::uint32_t r;
        const std::uint32_t m = rule(at + i, rk[i], r) ? ~0u : 0u;
        rk[i] = (r & m) | (rk[i] & ~m);
        const auto m8 = static_cast<std::uint8_t>(m);
        mask[3 * i] = m8;
        mask[3 * i + 1] = m8;
        mask[3 * i + 2] = m8;
      }
      std::uint8_t* __restrict d = dst + 3 * at;
      const std::uint8_t* __restrict s = src + 3 * at;
      for (int j = 0; j < 3 * len; ++j) {
        d[j] = static_cast<std::uint8_t>((s[j] & mask[j]) | (d[j] & ~mask[j]));
      }
    }
  }
}

template <bool kKeyed, int kBpp>
[[gnu::always_inline]] inline void overlay_span(std::uint8_t* __restrict dst,
                                                std::uint32_t* __restrict rank,
                                                const std::uint8_t* __restrict src, int n, int bpp,
                                                std::uint32_t key, std::uint32_t r) {
  const int step = kBpp ? kBpp : bpp;
  apply_span<kBpp>(dst, rank, src, n, bpp, [&](int i, std::uint32_t old, std::uint32_t& to) {
    to = r;
    return (r <= old) & (!kKeyed | (rgb_at(src + i * step) != key));
  });
}

template <int kBpp>
[[gnu::always_inline]] inline void depth_span(std::uint8_t* __restrict dst,
                                              std::uint32_t* __restrict rank,
                                              const std::uint8_t* __restrict src,
                                              const std::uint8_t* __restrict depth, int n, int bpp,
                                              std::uint32_t tag) {
  const int step = kBpp ? kBpp : bpp;
  apply_span<kBpp>(dst, rank, src, n, bpp, [&](int i, std::uint32_t old, std::uint32_t& to) {
    const std::uint32_t d = rgb_at(depth + i * step);
    const std::uint32_t r = (d + 1) << 8 | tag;
    to = r < kFar - 1 ? r : kFar - 1;  // depth FFFFFE from input 255 ranks as input 254's
    return (d < kFarDepth) & (to < old);
  });
}

// One entry point per loop shape: the clones are made per function.
L2_COMPOSITE_CLONES void copy3(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                               const std::uint8_t* __restrict src, int n, std::uint32_t r) {
  overlay_span<false, 3>(dst, rank, src, n, 3, 0, r);
}
L2_COMPOSITE_CLONES void copy4(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                               const std::uint8_t* __restrict src, int n, std::uint32_t r) {
  overlay_span<false, 4>(dst, rank, src, n, 4, 0, r);
}
L2_COMPOSITE_CLONES void key3(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                              const std::uint8_t* __restrict src, int n, std::uint32_t key,
                              std::uint32_t r) {
  overlay_span<true, 3>(dst, rank, src, n, 3, key, r);
}
L2_COMPOSITE_CLONES void key4(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                              const std::uint8_t* __restrict src, int n, std::uint32_t key,
                              std::uint32_t r) {
  overlay_span<true, 4>(dst, rank, src, n, 4, key, r);
}
L2_COMPOSITE_CLONES void depth3(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                                const std::uint8_t* __restrict src,
                                const std::uint8_t* __restrict depth, int n, std::uint32_t tag) {
  depth_span<3>(dst, rank, src, depth, n, 3, tag);
}
L2_COMPOSITE_CLONES void depth4(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                                const std::uint8_t* __restrict src,
                                const std::uint8_t* __restrict depth, int n, std::uint32_t tag) {
  depth_span<4>(dst, rank, src, depth, n, 4, tag);
}

L2_COMPOSITE_CLONES int settle_span(std::uint8_t* __restrict dst, std::uint32_t* __restrict rank,
                                    int n, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  int written = 0;
  const std::uint8_t bg[3] = {r, g, b};
  for (int i = 0; i < n; ++i) {
    const bool empty = rank[i] == kFar;
    written += static_cast<int>(!empty);
    select_colour(dst, i, bg, empty);
    rank[i] = kFar;
  }
  return written;
}

}  // namespace

void overlay(bool keyed, std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n,
             int bpp, std::uint32_t key, int input) {
  const std::uint32_t r = opaque_rank(input);
  if (bpp != 3 && bpp != 4) {  // wider pixels: no link carries them; not worth a clone
    keyed ? overlay_span<true, 0>(dst, rank, src, n, bpp, key, r)
          : overlay_span<false, 0>(dst, rank, src, n, bpp, 0, r);
    return;
  }
  // The AVX2 steps first (composite_simd.hpp), the plain loop for the rest of the span.
  const int done = simd::available() ? simd::overlay(keyed, dst, rank, src, n, bpp, key, r) : 0;
  dst += 3 * done;
  rank += done;
  src += bpp * done;
  n -= done;
  if (keyed) {
    bpp == 3 ? key3(dst, rank, src, n, key, r) : key4(dst, rank, src, n, key, r);
  } else {
    bpp == 3 ? copy3(dst, rank, src, n, r) : copy4(dst, rank, src, n, r);
  }
}

void depth(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
           const std::uint8_t* depth, int n, int bpp, int input) {
  const auto tag = static_cast<std::uint32_t>(input);
  if (bpp != 3 && bpp != 4) {
    depth_span<0>(dst, rank, src, depth, n, bpp, tag);
    return;
  }
  const int done = simd::available() ? simd::depth(dst, rank, src, depth, n, bpp, tag) : 0;
  dst += 3 * done;
  rank += done;
  src += bpp * done;
  depth += bpp * done;
  n -= done;
  bpp == 3 ? depth3(dst, rank, src, depth, n, tag) : depth4(dst, rank, src, depth, n, tag);
}

int settle(std::uint8_t* dst, std::uint32_t* rank, int n, std::uint8_t r, std::uint8_t g,
           std::uint8_t b) {
  int written = 0;
  const int done = simd::available() ? simd::settle(dst, rank, n, r, g, b, written) : 0;
  return written + settle_span(dst + 3 * done, rank + done, n - done, r, g, b);
}

}  // namespace l2::composite
