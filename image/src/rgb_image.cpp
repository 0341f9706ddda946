#include "image/rgb_image.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace l2 {

CacheLineBytes::CacheLineBytes(std::size_t size)
    : bytes_(size ? new (kAlign) std::uint8_t[size] : nullptr), size_(size) {}

CacheLineBytes::CacheLineBytes(const CacheLineBytes& other) : CacheLineBytes(other.size_) {
  if (size_) std::memcpy(bytes_.get(), other.bytes_.get(), size_);
}

CacheLineBytes& CacheLineBytes::operator=(const CacheLineBytes& other) {
  if (this != &other) *this = CacheLineBytes(other);
  return *this;
}

bool operator==(const CacheLineBytes& a, const CacheLineBytes& b) {
  return a.size_ == b.size_ && (a.size_ == 0 || std::memcmp(a.data(), b.data(), a.size_) == 0);
}

RgbImage::RgbImage(int width, int height, Unfilled) : width_(width), height_(height) {
  if (width < 0 || height < 0) throw std::invalid_argument("RgbImage: negative size");
  bytes_ = CacheLineBytes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                          kChannels);
}

RgbImage::RgbImage(int width, int height, Rgb fill_colour) : RgbImage(width, height, Unfilled{}) {
  fill(fill_colour);
}

RgbImage RgbImage::unfilled(int width, int height) {
  return RgbImage(width, height, Unfilled{});
}

Rgb RgbImage::at(int x, int y) const {
  const std::uint8_t* p = bytes_.data() + y * stride() + static_cast<std::size_t>(x) * kChannels;
  return {p[0], p[1], p[2]};
}

void RgbImage::set(int x, int y, Rgb c) {
  std::uint8_t* p = bytes_.data() + y * stride() + static_cast<std::size_t>(x) * kChannels;
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

void RgbImage::fill(Rgb c) {
  fill_rect(0, 0, width_, height_, c);
}

// One row's span pixel by pixel, the others copied from it (a grey: memset): every new image
// is filled, and the vizserver path makes several a frame, where a pixel-by-pixel fill of all of
// them showed in its profile.
void RgbImage::fill_rect(int x, int y, int w, int h, Rgb c) {
  const int x0 = std::max(x, 0), x1 = std::min(x + w, width_);
  const int y0 = std::max(y, 0), y1 = std::min(y + h, height_);
  if (x0 >= x1 || y0 >= y1) return;
  const std::size_t span = static_cast<std::size_t>(x1 - x0) * kChannels;
  // Whole rows are one block.
  const bool whole = x0 == 0 && x1 == width_;
  const int rows = whole ? 1 : y1 - y0;
  const std::size_t bytes = whole ? span * static_cast<std::size_t>(y1 - y0) : span;
  std::uint8_t* const first =
      bytes_.data() + y0 * stride() + static_cast<std::size_t>(x0) * kChannels;
  if (c.r == c.g && c.g == c.b) {
    for (int r = 0; r < rows; ++r) std::memset(first + r * stride(), c.r, bytes);
    return;
  }
  for (std::size_t i = 0; i < span; i += kChannels) {
    first[i] = c.r;
    first[i + 1] = c.g;
    first[i + 2] = c.b;
  }
  for (int yy = y0 + 1; yy < y1; ++yy) {
    std::memcpy(first + (yy - y0) * stride(), first, span);
  }
}

}  // namespace l2
