// A display's colour correction as one table per channel (docs/wall-file.md, "Colour matching"):
// every output byte is table[channel][input byte]. Gain and offset become such a table once, so
// a display has one per-pixel path whatever its correction was written as.
//
// Example:
//   const ColourTable t = colour_table_from_gain({1.0, 0.96, 0.92}, {0, 0, 4});
//   apply_colour(t, raw, shown);   // shown: raw's size, every byte looked up
#pragma once

#include <array>
#include <cstdint>

#include "image/rgb_image.hpp"

namespace l2 {

struct ColourTable {
  using Channel = std::array<std::uint8_t, 256>;
  std::array<Channel, RgbImage::kChannels> channel;  // R, G, B

  // Every channel maps each byte to itself.
  static ColourTable identity();
  bool is_identity() const;
  friend bool operator==(const ColourTable&, const ColourTable&) = default;
};

// Fixed point of a gain: the gain is taken to 1/2^kGainShift, so the table is exact integer
// arithmetic, the same on every machine and compiler. The step is that fine so that in * gain
// rounds the right way even where it lies close to a half (an edge blend's gains are powers of
// whole numbers of 4096ths, and at gamma 1 are then exact).
inline constexpr int kGainShift = 32;
inline constexpr double kMaxGain = 4.0;
inline constexpr int kMaxOffset = 255;

// out = clamp(floor((in * G + 2^31) / 2^32) + offset, 0, 255), G = round(gain * 2^32) (halves
// away from zero): in * gain rounded to the nearest integer, halves up, then the offset.
// Gains 0..kMaxGain, offsets -kMaxOffset..kMaxOffset (callers check). Colour matching and edge
// blending both make their tables here.
ColourTable colour_table_from_gain(const std::array<double, 3>& gain,
                                   const std::array<int, 3>& offset);

// The table that looks a byte up in `first`, then the result in `then`: two corrections applied
// in one lookup.
ColourTable compose(const ColourTable& first, const ColourTable& then);

// `out` becomes `in` with every byte looked up in its channel's table (resized to `in`'s size
// when it differs). `in` and `out` may be the same picture.
void apply_colour(const ColourTable& table, const RgbImage& in, RgbImage& out);

}  // namespace l2
