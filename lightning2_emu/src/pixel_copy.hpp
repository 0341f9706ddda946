// The router's pixel moves: strip pixels into a display row, background into the gaps.
//
// A display back buffer (23 MB for the 3200x2400 headline case) is far larger than the caches
// and is not read again until it is shown a frame later, so strips are written with streaming
// (non-temporal) stores: the lines go straight to memory instead of being read in first only to
// be overwritten, which is a third of the memory traffic of an ordinary copy. Only whole,
// aligned 64-byte lines are streamed; the partial lines at either end of a strip, which a
// neighbouring strip shares, are written normally. Streamed stores are weakly ordered:
// finish_streaming() must run before another thread reads the pixels.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "image/rgb_image.hpp"

namespace l2::pixel_copy {

constexpr int kLine = 64;

// N bytes, as one load and one store where the machine has them.
template <std::size_t N>
inline void move(std::uint8_t* dst, const std::uint8_t* src) {
  std::uint8_t bytes[N];
  std::memcpy(bytes, src, N);
  std::memcpy(dst, bytes, N);
}

// Fewer than 2 * N bytes (N = 32: the partial lines at a strip's ends): two moves of the
// largest power of two that fits, overlapping in the middle. Inline and branch-light, where a
// memcpy call of a size known only at run time costs several times as many instructions.
template <std::size_t N = 32>
inline void copy_short(std::uint8_t* dst, const std::uint8_t* src, std::size_t n) {
  if (n >= N) {
    move<N>(dst, src);
    move<N>(dst + n - N, src + n - N);
  } else if constexpr (N > 1) {
    copy_short<N / 2>(dst, src, n);
  }
}

// `bytes` bytes from src to dst, whole dst lines streamed.
inline void stream_bytes(std::uint8_t* dst, const std::uint8_t* src, std::size_t bytes) {
#if defined(__SSE2__)
  const std::size_t head = (kLine - reinterpret_cast<std::uintptr_t>(dst) % kLine) % kLine;
  if (bytes < head + kLine) {  // no whole line: nothing to gain
    std::memcpy(dst, src, bytes);
    return;
  }
  if (head) copy_short(dst, src, head);  // a strip that starts a line: no partial line
  std::size_t at = head;
  for (; at + kLine <= bytes; at += kLine) {
    const auto* s = reinterpret_cast<const __m128i*>(src + at);
    auto* d = reinterpret_cast<__m128i*>(dst + at);
    const __m128i a = _mm_loadu_si128(s), b = _mm_loadu_si128(s + 1);
    const __m128i c = _mm_loadu_si128(s + 2), e = _mm_loadu_si128(s + 3);
    _mm_stream_si128(d, a);
    _mm_stream_si128(d + 1, b);
    _mm_stream_si128(d + 2, c);
    _mm_stream_si128(d + 3, e);
  }
  if (at < bytes) copy_short(dst + at, src + at, bytes - at);
#else
  std::memcpy(dst, src, bytes);
#endif
}

// Makes this thread's streamed stores visible before it reports its task done.
inline void finish_streaming() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

// Strip pixels to a display row: RGB as bytes, RGBA dropping A.
inline void copy_pixels(std::uint8_t* dst, const std::uint8_t* src, int pixels, int bpp) {
  if (bpp == 3) {
    stream_bytes(dst, src, static_cast<std::size_t>(pixels) * 3);
    return;
  }
  for (int i = 0; i < pixels; ++i, dst += 3, src += bpp) {
    dst[0] = src[0];
    dst[1] = src[1];
    dst[2] = src[2];
  }
}

inline void fill_pixels(std::uint8_t* dst, int pixels, Rgb c) {
  if (c.r == c.g && c.g == c.b) {
    std::memset(dst, c.r, static_cast<std::size_t>(pixels) * 3);
    return;
  }
  for (int i = 0; i < pixels; ++i, dst += 3) {
    dst[0] = c.r;
    dst[1] = c.g;
    dst[2] = c.b;
  }
}

// Asks for the line holding p, to be read soon, into every cache level: a non-temporal
// prefetch fills only the first level, whose few miss buffers then cap how many lines are in
// flight (measured slower). GCC 12 took the scanner's prefetch_headers(), whose only work was
// __builtin_prefetch in a loop, for a function without effect and deleted its calls: the header
// prefetches were never executed. A volatile asm statement is never deleted.
inline void prefetch_line(const std::uint8_t* p) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*p));
#else
  __builtin_prefetch(p, 0, 3);
#endif
}

// The lines of `bytes` bytes from p.
inline void prefetch_bytes(const std::uint8_t* p, int bytes) {
  if (bytes <= 0) return;
  const std::uint8_t* const end = p + bytes;
  for (; p < end; p += kLine) prefetch_line(p);
  prefetch_line(end - 1);  // the last line, when p was not line-aligned
}

}  // namespace l2::pixel_copy
