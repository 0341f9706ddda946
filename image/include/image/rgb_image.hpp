// A 24-bit RGB picture, rows top to bottom (spec §1): the scanned-out frame on a DVI link, a
// display's buffer, a test-pattern tile. Rows are contiguous so strips copy as spans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <utility>

namespace l2 {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// Pixels start on a cache line: a row span whose width is a multiple of 64 bytes (a 64-pixel
// tile of a display whose row is too) then covers whole lines, which the emulator's router
// writes with streaming stores instead of reading partial lines in first. Not a std::vector
// with an aligning allocator: a vector built, copied or destroyed through any allocator but
// std::allocator goes byte by byte, which the unoptimised command-line and test files
// (cmake/Targets.cmake) paid for every picture.
class CacheLineBytes {
 public:
  CacheLineBytes() = default;
  explicit CacheLineBytes(std::size_t size);  // uninitialised
  CacheLineBytes(const CacheLineBytes& other);
  CacheLineBytes& operator=(const CacheLineBytes& other);
  CacheLineBytes(CacheLineBytes&& other) noexcept
      : bytes_(std::move(other.bytes_)), size_(std::exchange(other.size_, 0)) {}
  CacheLineBytes& operator=(CacheLineBytes&& other) noexcept {
    bytes_ = std::move(other.bytes_);
    size_ = std::exchange(other.size_, 0);
    return *this;
  }

  std::uint8_t* data() { return bytes_.get(); }
  const std::uint8_t* data() const { return bytes_.get(); }
  std::size_t size() const { return size_; }

  friend bool operator==(const CacheLineBytes& a, const CacheLineBytes& b);

 private:
  static constexpr std::align_val_t kAlign{64};
  struct Free {
    void operator()(std::uint8_t* p) const { ::operator delete[](p, kAlign); }
  };
  std::unique_ptr<std::uint8_t[], Free> bytes_;
  std::size_t size_ = 0;
};

class RgbImage {
 public:
  static constexpr int kChannels = 3;

  RgbImage() = default;
  RgbImage(int width, int height, Rgb fill = {});
  // Pixels left as the allocator gives them, for a caller that writes every byte next (a
  // picture received whole): filling first would be one more pass over all of it.
  static RgbImage unfilled(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t stride() const { return static_cast<std::size_t>(width_) * kChannels; }
  bool empty() const { return width_ == 0 || height_ == 0; }

  std::span<std::uint8_t> row(int y) { return {bytes_.data() + y * stride(), stride()}; }
  std::span<const std::uint8_t> row(int y) const {
    return {bytes_.data() + y * stride(), stride()};
  }
  std::uint8_t* data() { return bytes_.data(); }
  const std::uint8_t* data() const { return bytes_.data(); }
  // Every row, stride() bytes each.
  std::span<std::uint8_t> bytes() { return {bytes_.data(), bytes_.size()}; }
  std::span<const std::uint8_t> bytes() const { return {bytes_.data(), bytes_.size()}; }

  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
  void fill(Rgb c);
  // Fills the rectangle clipped to the image.
  void fill_rect(int x, int y, int w, int h, Rgb c);

  friend bool operator==(const RgbImage&, const RgbImage&) = default;

 private:
  struct Unfilled {};
  RgbImage(int width, int height, Unfilled);

  int width_ = 0;
  int height_ = 0;
  CacheLineBytes bytes_;
};

}  // namespace l2
