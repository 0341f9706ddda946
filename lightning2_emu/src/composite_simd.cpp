// composite_simd.hpp for x86-64 with GCC: the functions below the pragma are compiled for AVX2
// and called only when the machine has it (no load-time resolver: under ThreadSanitizer one
// crashed before the runtime was set up). Every header is included above the pragma, so no
// inline function of theirs is compiled for AVX2 here and picked by the linker for other files.
#include "composite_simd.hpp"

#include "composite.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define L2_COMPOSITE_AVX2 1
#else
#define L2_COMPOSITE_AVX2 0
#endif

namespace l2::composite::simd {

#if L2_COMPOSITE_AVX2

bool available() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

#pragma GCC push_options
#pragma GCC target("avx2")

namespace {

inline __m256i load(const void* p) {
  return _mm256_loadu_si256(static_cast<const __m256i*>(p));
}
inline void store(void* p, __m256i v) {
  _mm256_storeu_si256(static_cast<__m256i*>(p), v);
}
// Bytes 0-23 of p as load() places them, 24-31 zero, reading nothing past the 24: the last
// step of a span, whose next bytes may lie past the end of the frame or display.
inline __m256i load24(const std::uint8_t* p) {
  const __m128i low = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i high = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + 16));
  return _mm256_inserti128_si256(_mm256_castsi128_si256(low), high, 1);
}
// Eight RGB pixels: 32 bytes read inside a span, exactly 24 at its end (kLast).
template <bool kLast>
inline __m256i load_rgb(const std::uint8_t* p) {
  if constexpr (kLast) {
    return load24(p);
  } else {
    return load(p);
  }
}

// The byte shuffle that makes 32-bit lanes of the four pixels in each 128-bit half: lane byte
// b + up holds colour byte 2 - b of its pixel (the lane is R << 16 | G << 8 | B, << 8 with up).
template <int kBpp, bool kUp>
struct LaneOrder {
  alignas(32) std::int8_t at[32]{};
  constexpr LaneOrder() {
    for (int k = 0; k < 32; ++k) {
      const int pixel = k % 16 / 4, b = k % 4 - (kUp ? 1 : 0);
      at[k] = static_cast<std::int8_t>(b >= 0 && b < 3 ? pixel * kBpp + 2 - b : -1);
    }
  }
};
template <int kBpp, bool kUp>
inline constexpr LaneOrder<kBpp, kUp> kLaneOrder;

// Eight pixels of kBpp bytes as 32-bit lanes R << 16 | G << 8 | B, or that << 8 (kUp). Byte
// shuffles stay inside 128-bit halves, so RGB pixels 4-7 (bytes 12-23) first move to the upper.
template <int kBpp, bool kUp = false, bool kLast = false>
inline __m256i lanes(const std::uint8_t* p) {
  const __m256i order =
      _mm256_load_si256(reinterpret_cast<const __m256i*>(kLaneOrder<kBpp, kUp>.at));
  if constexpr (kBpp == 3) {
    const __m256i halves =
        _mm256_permutevar8x32_epi32(load_rgb<kLast>(p), _mm256_setr_epi32(0, 1, 2, 0, 3, 4, 5, 0));
    return _mm256_shuffle_epi8(halves, order);
  } else {
    return _mm256_shuffle_epi8(load(p), order);
  }
}

// Eight pixels' colours as the first 24 bytes, R G B R G B ... (RGBA: A dropped).
template <int kBpp, bool kLast = false>
inline __m256i colours(const std::uint8_t* p) {
  if constexpr (kBpp == 3) {
    return load_rgb<kLast>(p);
  } else {
    const __m256i packed = _mm256_shuffle_epi8(
        load(p), _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1, 0, 1, 2,
                                  4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1));
    return _mm256_permutevar8x32_epi32(packed, _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 3));
  }
}

// Eight 32-bit lane masks as 24 byte masks, three a pixel; bytes 24-31 zero.
inline __m256i spread(__m256i m) {
  const __m256i bytes = _mm256_shuffle_epi8(
      m, _mm256_setr_epi8(0, 0, 0, 4, 4, 4, 8, 8, 8, 12, 12, 12, -1, -1, -1, -1, 0, 0, 0, 4, 4, 4,
                          8, 8, 8, 12, 12, 12, -1, -1, -1, -1));
  return _mm256_permutevar8x32_epi32(bytes, _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 3));
}

// Where the steps stop (see the header): 8 pixels each, none within 11 of the end.
inline int stop(int n) {
  return n - 10;
}

// The first 24 bytes of v to p. Not 32 with the last 8 unchanged: the next step's load of
// those bytes would then wait until the store had left the core (a load that a store before it
// covers only in part is not forwarded from it), which cost more than the two stores.
inline void store24(std::uint8_t* p, __m256i v) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm256_castsi256_si128(v));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(p + 16), _mm256_extracti128_si256(v, 1));
}

// Rank and colour of eight pixels replaced where `write`.
template <bool kLast>
inline void select(std::uint8_t* dst, std::uint32_t* rank, __m256i old, __m256i to, __m256i write,
                   __m256i colour) {
  store(rank, _mm256_blendv_epi8(old, to, write));
  store24(dst, _mm256_blendv_epi8(load_rgb<kLast>(dst), colour, spread(write)));
}

// The last step of a span of n >= 8 pixels whose steps stopped at i: pixels n-8 to n-1, the
// first of them again. Applying a strip pixel twice leaves what applying it once did (an
// opaque pixel of equal rank writes the same colour again, a DEPTH pixel of equal rank is not
// nearer), so the overlap changes nothing and the plain loop has nothing left: its calls, a
// few pixels each, cost as much as a sixth of the steps in the profile.
inline bool last_step(int n, int i) {
  return n >= 8 && i < n;
}

template <bool kKeyed, int kBpp, bool kLast>
inline void overlay_step(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* s, __m256i to,
                         __m256i key_lanes) {
  const __m256i old = load(rank);
  __m256i write = _mm256_cmpeq_epi32(_mm256_min_epu32(to, old), to);  // r <= old
  if constexpr (kKeyed) {
    write = _mm256_andnot_si256(_mm256_cmpeq_epi32(lanes<kBpp, false, kLast>(s), key_lanes), write);
  }
  select<kLast>(dst, rank, old, to, write, colours<kBpp, kLast>(s));
}

template <bool kKeyed, int kBpp>
int overlay_steps(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n,
                  std::uint32_t key, std::uint32_t r) {
  const __m256i to = _mm256_set1_epi32(static_cast<int>(r));
  const __m256i key_lanes = _mm256_set1_epi32(static_cast<int>(key));
  int i = 0;
  for (; i < stop(n); i += 8) {
    overlay_step<kKeyed, kBpp, false>(dst + 3 * i, rank + i, src + i * kBpp, to, key_lanes);
  }
  for (; n - i > 8; i += 8) {
    overlay_step<kKeyed, kBpp, true>(dst + 3 * i, rank + i, src + i * kBpp, to, key_lanes);
  }
  if (!last_step(n, i)) return i;
  const int at = n - 8;
  overlay_step<kKeyed, kBpp, true>(dst + 3 * at, rank + at, src + at * kBpp, to, key_lanes);
  return n;
}

// Ranks (D + 1) << 8 | tag, as (D << 8) + (256 | tag): the byte shuffle that takes the depths
// apart puts them 8 bits up. Where a pixel is kept (far plane, or a rank not below the pixel's)
// the blends take the old values, so the mask needs no inverting.
template <int kBpp, bool kInput255, bool kLast>
inline void depth_step(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
                       const std::uint8_t* depth, std::uint32_t tag) {
  const __m256i above = _mm256_set1_epi32(static_cast<int>(256 | tag));
  const __m256i far_plane = _mm256_set1_epi32(static_cast<int>(kFarDepth << 8));
  const __m256i last_rank = _mm256_set1_epi32(static_cast<int>(kFar - 1));
  const __m256i d8 = lanes<kBpp, true, kLast>(depth);
  __m256i to = _mm256_add_epi32(d8, above);
  if constexpr (kInput255) to = _mm256_min_epu32(to, last_rank);  // FFFFFE as input 254's
  const __m256i old = load(rank);
  const __m256i keep = _mm256_or_si256(_mm256_cmpeq_epi32(d8, far_plane),
                                       _mm256_cmpeq_epi32(_mm256_max_epu32(to, old), to));
  store(rank, _mm256_blendv_epi8(to, old, keep));
  store24(dst, _mm256_blendv_epi8(colours<kBpp, kLast>(src), load_rgb<kLast>(dst), spread(keep)));
}

template <int kBpp, bool kInput255>
int depth_steps(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
                const std::uint8_t* depth, int n, std::uint32_t tag) {
  int i = 0;
  for (; i < stop(n); i += 8) {
    depth_step<kBpp, kInput255, false>(dst + 3 * i, rank + i, src + i * kBpp, depth + i * kBpp,
                                       tag);
  }
  for (; n - i > 8; i += 8) {
    depth_step<kBpp, kInput255, true>(dst + 3 * i, rank + i, src + i * kBpp, depth + i * kBpp, tag);
  }
  if (!last_step(n, i)) return i;
  const int at = n - 8;
  depth_step<kBpp, kInput255, true>(dst + 3 * at, rank + at, src + at * kBpp, depth + at * kBpp,
                                    tag);
  return n;
}

}  // namespace

int overlay(bool keyed, std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n,
            int bpp, std::uint32_t key, std::uint32_t r) {
  if (bpp == 3) {
    return keyed ? overlay_steps<true, 3>(dst, rank, src, n, key, r)
                 : overlay_steps<false, 3>(dst, rank, src, n, key, r);
  }
  return keyed ? overlay_steps<true, 4>(dst, rank, src, n, key, r)
               : overlay_steps<false, 4>(dst, rank, src, n, key, r);
}

int depth(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
          const std::uint8_t* depth, int n, int bpp, std::uint32_t tag) {
  if (tag == 255) {
    return bpp == 3 ? depth_steps<3, true>(dst, rank, src, depth, n, tag)
                    : depth_steps<4, true>(dst, rank, src, depth, n, tag);
  }
  return bpp == 3 ? depth_steps<3, false>(dst, rank, src, depth, n, tag)
                  : depth_steps<4, false>(dst, rank, src, depth, n, tag);
}

int settle(std::uint8_t* dst, std::uint32_t* rank, int n, std::uint8_t r, std::uint8_t g,
           std::uint8_t b, int& written) {
  // The background as 32 bytes R G B R G B ...: a step starts on a pixel, so every step's
  // first 24 bytes line up with it.
  alignas(32) std::uint8_t pattern[32];
  for (int k = 0; k < 32; ++k) pattern[k] = k % 3 == 0 ? r : k % 3 == 1 ? g : b;
  const __m256i background = load(pattern);
  const __m256i far = _mm256_set1_epi32(-1);
  __m256i empties = _mm256_setzero_si256();  // minus the empty pixels, lane by lane
  const __m256i every = _mm256_set1_epi32(-1);
  // Eight pixels from `at`, those of the lanes in `judged`. Most pixels of a composited display
  // were written: their colours are left unread.
  const auto step = [&](int at, __m256i judged) {
    const __m256i empty = _mm256_and_si256(_mm256_cmpeq_epi32(load(rank + at), far), judged);
    empties = _mm256_add_epi32(empties, empty);
    store(rank + at, far);
    if (!_mm256_testz_si256(empty, empty)) {
      store24(dst + 3 * at, _mm256_blendv_epi8(load24(dst + 3 * at), background, spread(empty)));
    }
  };
  int i = 0;
  for (; n - i > 8; i += 8) step(i, every);
  if (last_step(n, i)) {
    // Pixels n-8 to n-1 again, as the other loops end; but settled pixels look empty (kFar),
    // so only the lanes of pixels i and on (the last n - i) are judged.
    step(n - 8, _mm256_cmpgt_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7),
                                   _mm256_set1_epi32(7 - (n - i))));
    i = n;
  }
  alignas(32) std::int32_t lane[8];
  store(lane, empties);
  written += i;
  for (const std::int32_t e : lane) written += e;
  return i;
}

#pragma GCC pop_options

#else

bool available() {
  return false;
}
int overlay(bool, std::uint8_t*, std::uint32_t*, const std::uint8_t*, int, int, std::uint32_t,
            std::uint32_t) {
  return 0;
}
int depth(std::uint8_t*, std::uint32_t*, const std::uint8_t*, const std::uint8_t*, int, int,
          std::uint32_t) {
  return 0;
}
int settle(std::uint8_t*, std::uint32_t*, int, std::uint8_t, std::uint8_t, std::uint8_t, int&) {
  return 0;
}

#endif

}  // namespace l2::composite::simd
