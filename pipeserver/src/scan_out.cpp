#include "pipeserver/scan_out.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define L2_SCAN_OUT_SSSE3 1
#endif

namespace l2 {

namespace {

// Four pixels at a time: read 16 bytes, write 12. Written with fixed-size memcpy so the compiler
// turns it into plain loads and stores, whatever the alignment.
void rgba_row_to_rgb(const std::uint8_t* src, std::uint8_t* dst, int width) {
  int x = 0;
  for (; x + 4 <= width; x += 4, src += 16, dst += 12) {
    std::uint8_t tmp[16];
    std::memcpy(tmp, src, 16);
    dst[0] = tmp[0], dst[1] = tmp[1], dst[2] = tmp[2];
    dst[3] = tmp[4], dst[4] = tmp[5], dst[5] = tmp[6];
    dst[6] = tmp[8], dst[7] = tmp[9], dst[8] = tmp[10];
    dst[9] = tmp[12], dst[10] = tmp[13], dst[11] = tmp[14];
  }
  for (; x < width; ++x, src += 4, dst += 3) {
    dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
  }
}

#ifdef L2_SCAN_OUT_SSSE3
// Sixteen pixels at a time with SSSE3 byte shuffles: each 16-byte load of four RGBA pixels packs
// to 12 RGB bytes, and four of those make three 16-byte stores. About four times the scalar
// loop's speed; every x86-64 CPU of the last fifteen years has SSSE3, checked once per frame.
__attribute__((target("ssse3"))) void rgba_row_to_rgb_ssse3(const std::uint8_t* src,
                                                            std::uint8_t* dst, int width) {
  const __m128i pack = _mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
  int x = 0;
  for (; x + 16 <= width; x += 16, src += 64, dst += 48) {
    const __m128i a =
        _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src)), pack);
    const __m128i b =
        _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 16)), pack);
    const __m128i c =
        _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 32)), pack);
    const __m128i d =
        _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + 48)), pack);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), _mm_or_si128(a, _mm_slli_si128(b, 12)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + 16),
                     _mm_or_si128(_mm_srli_si128(b, 4), _mm_slli_si128(c, 8)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + 32),
                     _mm_or_si128(_mm_srli_si128(c, 8), _mm_slli_si128(d, 4)));
  }
  rgba_row_to_rgb(src, dst, width - x);
}

bool have_ssse3() {
  static const bool yes = __builtin_cpu_supports("ssse3");
  return yes;
}
#endif

// `after_row(y, row)` runs on each scanline right after it is converted, while it is in the cache.
template <class RowFn, class AfterRow>
void scan_rows(const std::uint8_t* rgba, int width, int height, std::uint8_t* dst, RowFn row_fn,
               AfterRow after_row) {
  const std::size_t w = static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y) {
    // GL row 0 is the bottom scanline; scan-out row 0 is the top.
    std::uint8_t* row = dst + static_cast<std::size_t>(y) * w * 3;
    row_fn(rgba + static_cast<std::size_t>(height - 1 - y) * w * 4, row, width);
    after_row(y, std::span<std::uint8_t>(row, w * 3));
  }
}

void check_destination(int width, int height, std::span<std::uint8_t> dst_rgb) {
  if (width < 0 || height < 0) throw std::invalid_argument("scan_out: negative size");
  const std::size_t need = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  if (dst_rgb.size() < need) {
    throw std::invalid_argument(
        fmt::format("scan_out: destination holds {} bytes, {}x{} RGB needs {}", dst_rgb.size(),
                    width, height, need));
  }
}

template <class AfterRow>
void scan_out_rows(const std::uint8_t* rgba, int width, int height, std::uint8_t* dst,
                   AfterRow after_row) {
#ifdef L2_SCAN_OUT_SSSE3
  if (have_ssse3()) {
    scan_rows(rgba, width, height, dst, rgba_row_to_rgb_ssse3, after_row);
    return;
  }
#endif
  scan_rows(rgba, width, height, dst, rgba_row_to_rgb, after_row);
}

}  // namespace

void rgba_to_rgb_row(const std::uint8_t* rgba, std::uint8_t* rgb, int width) {
#ifdef L2_SCAN_OUT_SSSE3
  if (have_ssse3()) return rgba_row_to_rgb_ssse3(rgba, rgb, width);
#endif
  rgba_row_to_rgb(rgba, rgb, width);
}

void scan_out(const std::uint8_t* rgba, int width, int height, std::span<std::uint8_t> dst_rgb) {
  check_destination(width, height, dst_rgb);
  scan_out_rows(rgba, width, height, dst_rgb.data(), [](int, std::span<std::uint8_t>) {});
}

void scan_out(const std::uint8_t* rgba, int width, int height, std::span<std::uint8_t> dst_rgb,
              const FrameHeaders& headers) {
  check_destination(width, height, dst_rgb);
  if (headers.width() != width || headers.height() != height) {
    throw std::invalid_argument(fmt::format("scan_out: headers for {}x{}, the frame is {}x{}",
                                            headers.width(), headers.height(), width, height));
  }
  scan_out_rows(rgba, width, height, dst_rgb.data(),
                [&headers](int y, std::span<std::uint8_t> row) { headers.draw_row(y, row); });
}

}  // namespace l2
