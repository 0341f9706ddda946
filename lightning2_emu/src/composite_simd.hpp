// The compositing loops of composite.hpp written out for AVX2, eight pixels a step: what GCC's
// vectoriser made of the plain loops spent most of its instructions taking three-byte pixels
// apart and putting them together (byte unpacks, packs, zero-extensions a pixel lane). Here a
// step reads each colour and depth pixel once with one load, turns eight depths (or key colours)
// into 32-bit lanes with one permute and one byte shuffle, compares and selects the ranks, and
// blends the eight colours as bytes under a mask spread the same way back.
//
// Each returns how many leading pixels of the span it did: all of a span of 8 or more, none of
// a shorter one or where the machine lacks AVX2; the caller's plain loop does the rest. A step
// loads 32 bytes for its 24 of RGB pixels, so the steps stop 11 pixels before the span's end
// (the bytes past a span may be past the end of the frame or display) and one last step, with
// loads of exactly 24 bytes, does its last 8 pixels, some of them a second time.
#pragma once

#include <cstdint>

namespace l2::composite::simd {

// Whether this machine runs the loops below (checked once).
bool available();

// COPY (keyed false) or KEY pixels, `bpp` 3 or 4, rank `r` (composite.cpp has the rules).
int overlay(bool keyed, std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src, int n,
            int bpp, std::uint32_t key, std::uint32_t r);
// DEPTH pixels, `bpp` 3 or 4, ranks (D + 1) << 8 | tag.
int depth(std::uint8_t* dst, std::uint32_t* rank, const std::uint8_t* src,
          const std::uint8_t* depth, int n, int bpp, std::uint32_t tag);
// Background where the rank is kFar, every rank to kFar; `written` += pixels not background.
int settle(std::uint8_t* dst, std::uint32_t* rank, int n, std::uint8_t r, std::uint8_t g,
           std::uint8_t b, int& written);

}  // namespace l2::composite::simd
