#include "dvi_link/frame_delta.hpp"

#include <fmt/format.h>
#include <lz4.h>
#include <zstd.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "base/little_endian.hpp"

namespace l2 {
namespace {

constexpr std::array<std::uint8_t, 4> kMagic = {'L', '2', 'F', 'D'};
constexpr std::uint8_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 24;
constexpr std::uint8_t kTemporal = 0, kSpatial = 1;
// zstd's fastest levels: a frame must be compressed faster than a link carries it.
constexpr int kZstdLevel = 1;

std::size_t bitmap_bytes(int height) {
  return (static_cast<std::size_t>(height) + 7) / 8;
}

// How far a residual is from all zeros, as PNG's encoders choose a filter: the sum of its
// bytes taken as signed. The loops below are written plainly (one pass, 32-bit sums) so the
// compiler vectorises them (this file is built at -O3).
std::uint32_t magnitude(std::uint8_t residual) {
  const int v = static_cast<std::int8_t>(residual);
  return static_cast<std::uint32_t>(v < 0 ? -v : v);
}

// out = row ^ previous; returns its weight.
std::uint32_t temporal(const std::uint8_t* row, const std::uint8_t* previous, std::uint8_t* out,
                       std::size_t n) {
  std::uint32_t sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = static_cast<std::uint8_t>(row[i] ^ previous[i]);
    sum += magnitude(out[i]);
  }
  return sum;
}

// out = row minus the pixel to its left (the first pixel as it is); returns its weight.
std::uint32_t spatial(const std::uint8_t* row, std::uint8_t* out, std::size_t n) {
  std::uint32_t sum = 0;
  const std::size_t first = std::min<std::size_t>(3, n);
  for (std::size_t i = 0; i < first; ++i) {
    out[i] = row[i];
    sum += magnitude(out[i]);
  }
  for (std::size_t i = 3; i < n; ++i) {
    out[i] = static_cast<std::uint8_t>(row[i] - row[i - 3]);
    sum += magnitude(out[i]);
  }
  return sum;
}

}  // namespace

Result<LinkCodec> parse_link_codec(std::string_view text) {
  if (text == "raw") return LinkCodec::Raw;
  if (text == "lz4") return LinkCodec::Lz4;
  if (text == "zstd") return LinkCodec::Zstd;
  if (text == "whole") return LinkCodec::Whole;
  return Failure{fmt::format("'{}' is not a link codec: raw, lz4, zstd or whole", text)};
}

std::string_view link_codec_name(LinkCodec codec) {
  switch (codec) {
    case LinkCodec::Raw:
      return "raw";
    case LinkCodec::Lz4:
      return "lz4";
    case LinkCodec::Zstd:
      return "zstd";
    case LinkCodec::Whole:
      return "whole";
  }
  return "?";
}

Result<std::optional<LinkCodec>> parse_link_choice(std::string_view text) {
  if (text == "auto") return std::optional<LinkCodec>();
  Result<LinkCodec> codec = parse_link_codec(text);
  if (!codec.ok()) return Failure{fmt::format("'{}' is not auto, raw, lz4, zstd or whole", text)};
  return std::optional<LinkCodec>(codec.value());
}

std::string_view link_choice_help() {
  return "how frames travel to the board columns (--mpi) and tiles to the compositing server: "
         "zstd, lz4 or raw send what changed since the last frame (unchanged rows dropped, "
         "changed ones predicted, then compressed, or not for raw), whole sends every row as it "
         "is; auto: zstd to a machine of its own, whole on the same machine, where a copy costs "
         "less. Lossless: the displays are the same bytes";
}

std::size_t whole_frame_prefix_bytes(int height) {
  return kHeaderBytes + bitmap_bytes(height);
}

void write_whole_frame_prefix(int width, int height, std::span<std::uint8_t> out) {
  const std::size_t bitmap = bitmap_bytes(height);
  if (out.size() < kHeaderBytes + bitmap)
    throw std::invalid_argument("frame delta: no room for a whole frame's header");
  std::uint8_t* h = out.data();
  std::memcpy(h, kMagic.data(), kMagic.size());
  h[4] = kVersion;
  h[5] = static_cast<std::uint8_t>(LinkCodec::Whole);
  h[6] = h[7] = 0;
  const std::size_t frame = static_cast<std::size_t>(width) * 3 * static_cast<std::size_t>(height);
  put_u32(h + 8, static_cast<std::uint32_t>(width));
  put_u32(h + 12, static_cast<std::uint32_t>(height));
  put_u32(h + 16, static_cast<std::uint32_t>(height));
  put_u32(h + 20, static_cast<std::uint32_t>(frame));
  std::fill(h + kHeaderBytes, h + kHeaderBytes + bitmap, std::uint8_t{0xFF});
  if (height % 8 != 0)
    h[kHeaderBytes + bitmap - 1] = static_cast<std::uint8_t>((1u << (height % 8)) - 1);
}

std::size_t max_frame_delta_bytes(int width, int height) {
  const std::size_t rows = static_cast<std::size_t>(height);
  return kHeaderBytes + bitmap_bytes(height) + rows * (1 + static_cast<std::size_t>(width) * 3);
}

void FrameDeltaEncoder::ZstdFree::operator()(ZSTD_CCtx_s* context) const {
  ZSTD_freeCCtx(context);
}

FrameDeltaEncoder::FrameDeltaEncoder(int width, int height, LinkCodec codec)
    : width_(width),
      height_(height),
      stride_(static_cast<std::size_t>(width) * 3),
      codec_(codec),
      bitmap_(bitmap_bytes(height)) {
  if (codec == LinkCodec::Whole) return;  // no prediction: nothing kept between frames
  previous_.assign(stride_ * static_cast<std::size_t>(height), 0);
  masked_.resize(stride_);
  spatial_.resize(stride_);
  block_.reserve(static_cast<std::size_t>(height) * (1 + stride_));
  if (codec == LinkCodec::Zstd) zstd_.reset(ZSTD_createCCtx());
}

std::span<const std::uint8_t> FrameDeltaEncoder::encode(std::span<const std::uint8_t> frame,
                                                        std::span<const BlankRect> blank) {
  const std::size_t bytes = stride_ * static_cast<std::size_t>(height_);
  if (frame.size() != bytes)
    throw std::invalid_argument(fmt::format("frame delta: a {}x{} frame is {} bytes, got {}",
                                            width_, height_, bytes, frame.size()));
  if (codec_ == LinkCodec::Whole) return encode_whole(frame, blank);
  std::fill(bitmap_.begin(), bitmap_.end(), std::uint8_t{0});
  block_.clear();
  changed_ = 0;
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* row = frame.data() + stride_ * static_cast<std::size_t>(y);
    bool masked = false;
    for (const BlankRect& r : blank) {
      if (y < r.y || y >= r.y + r.h) continue;
      if (!masked) std::memcpy(masked_.data(), row, stride_);
      masked = true;
      const int x0 = std::clamp(r.x, 0, width_), x1 = std::clamp(r.x + r.w, 0, width_);
      if (x1 > x0)
        std::memset(masked_.data() + static_cast<std::size_t>(x0) * 3, 0,
                    static_cast<std::size_t>(x1 - x0) * 3);
    }
    encode_row(y, masked ? masked_.data() : row);
  }

  message_.resize(kHeaderBytes + bitmap_.size() +
                  std::max(block_.size(), codec_ == LinkCodec::Lz4
                                              ? static_cast<std::size_t>(LZ4_compressBound(
                                                    static_cast<int>(block_.size())))
                                              : ZSTD_compressBound(block_.size())));
  std::uint8_t* out = message_.data() + kHeaderBytes + bitmap_.size();
  const std::size_t room = message_.size() - kHeaderBytes - bitmap_.size();
  std::size_t packed = 0;
  LinkCodec used = codec_;
  if (codec_ == LinkCodec::Lz4 && !block_.empty()) {
    packed = static_cast<std::size_t>(LZ4_compress_default(
        reinterpret_cast<const char*>(block_.data()), reinterpret_cast<char*>(out),
        static_cast<int>(block_.size()), static_cast<int>(room)));
  } else if (codec_ == LinkCodec::Zstd && !block_.empty()) {
    const std::size_t n =
        ZSTD_compressCCtx(zstd_.get(), out, room, block_.data(), block_.size(), kZstdLevel);
    packed = ZSTD_isError(n) ? 0 : n;
  }
  if (packed == 0 || packed >= block_.size()) {  // not smaller: stored as it is
    used = LinkCodec::Raw;
    packed = block_.size();
    std::memcpy(out, block_.data(), packed);
  }
  message_.resize(kHeaderBytes + bitmap_.size() + packed);
  std::uint8_t* h = message_.data();
  std::memcpy(h, kMagic.data(), kMagic.size());
  h[4] = kVersion;
  h[5] = static_cast<std::uint8_t>(used);
  h[6] = h[7] = 0;
  put_u32(h + 8, static_cast<std::uint32_t>(width_));
  put_u32(h + 12, static_cast<std::uint32_t>(height_));
  put_u32(h + 16, changed_);
  put_u32(h + 20, static_cast<std::uint32_t>(packed));
  std::memcpy(h + kHeaderBytes, bitmap_.data(), bitmap_.size());
  return message_;
}

std::span<const std::uint8_t> FrameDeltaEncoder::encode_whole(std::span<const std::uint8_t> frame,
                                                              std::span<const BlankRect> blank) {
  const std::size_t prefix = whole_frame_prefix_bytes(height_);
  message_.resize(prefix + frame.size());
  write_whole_frame_prefix(width_, height_, message_);
  std::uint8_t* out = message_.data() + prefix;
  std::memcpy(out, frame.data(), frame.size());
  for (const BlankRect& r : blank) {
    const int x0 = std::clamp(r.x, 0, width_), x1 = std::clamp(r.x + r.w, 0, width_);
    for (int y = std::max(r.y, 0); y < std::min(r.y + r.h, height_) && x1 > x0; ++y)
      std::memset(out + stride_ * static_cast<std::size_t>(y) + static_cast<std::size_t>(x0) * 3, 0,
                  static_cast<std::size_t>(x1 - x0) * 3);
  }
  return message_;
}

// One row: unchanged (nothing sent), or the prediction that leaves the smaller residual.
void FrameDeltaEncoder::encode_row(int y, const std::uint8_t* row) {
  std::uint8_t* previous = previous_.data() + stride_ * static_cast<std::size_t>(y);
  if (std::memcmp(row, previous, stride_) == 0) return;
  bitmap_[static_cast<std::size_t>(y) / 8] |= static_cast<std::uint8_t>(1u << (y % 8));
  ++changed_;
  const std::size_t at = block_.size();
  block_.resize(at + 1 + stride_);
  std::uint8_t* residual = block_.data() + at + 1;
  const std::uint32_t in_time = temporal(row, previous, residual, stride_);
  // A row that changed in a few bytes (a header's parity) needs no second look.
  if (in_time > stride_ / 16 && spatial(row, spatial_.data(), stride_) < in_time) {
    block_[at] = kSpatial;
    std::memcpy(residual, spatial_.data(), stride_);
  } else {
    block_[at] = kTemporal;
  }
  std::memcpy(previous, row, stride_);
}

FrameDeltaDecoder::FrameDeltaDecoder(int width, int height)
    : width_(width),
      height_(height),
      stride_(static_cast<std::size_t>(width) * 3),
      frame_(stride_ * static_cast<std::size_t>(height), 0),
      block_(static_cast<std::size_t>(height) * (1 + stride_)) {}

Status FrameDeltaDecoder::decode(std::span<const std::uint8_t> message) {
  const Result<LinkCodec> checked = check(message);
  if (!checked.ok()) return Failure{checked.reason()};
  const LinkCodec codec = checked.value();
  const std::size_t bitmap = bitmap_bytes(height_);
  const std::uint8_t* h = message.data();
  const std::uint32_t changed = get_u32(h + 16), packed = get_u32(h + 20);
  const std::uint8_t* rows = h + kHeaderBytes;
  const std::uint8_t* in = rows + bitmap;
  if (codec == LinkCodec::Whole) {
    std::memcpy(frame_.data(), in, frame_.size());
    return {};
  }
  const std::size_t expected = std::size_t{changed} * (1 + stride_);
  std::size_t got = 0;
  if (codec == LinkCodec::Raw) {
    got = packed;
    if (got == expected) std::memcpy(block_.data(), in, got);
  } else if (codec == LinkCodec::Lz4) {
    const int n = LZ4_decompress_safe(reinterpret_cast<const char*>(in),
                                      reinterpret_cast<char*>(block_.data()),
                                      static_cast<int>(packed), static_cast<int>(expected));
    got = n < 0 ? expected + 1 : static_cast<std::size_t>(n);
  } else {
    const std::size_t n = ZSTD_decompress(block_.data(), expected, in, packed);
    got = ZSTD_isError(n) ? expected + 1 : n;
  }
  if (got != expected)
    return Failure{fmt::format("the {} block does not give the {} bytes of {} changed rows",
                               link_codec_name(codec), expected, changed)};
  return apply(rows, changed);
}

Status FrameDeltaDecoder::check_whole(std::span<const std::uint8_t> message) const {
  const Result<LinkCodec> checked = check(message);
  if (!checked.ok()) return Failure{checked.reason()};
  if (checked.value() != LinkCodec::Whole) return Failure{"not a whole frame"};
  return {};
}

Result<LinkCodec> FrameDeltaDecoder::check(std::span<const std::uint8_t> message) const {
  const std::size_t bitmap = bitmap_bytes(height_);
  if (message.size() < kHeaderBytes + bitmap)
    return Failure{fmt::format("a frame message of {} bytes is shorter than its header ({})",
                               message.size(), kHeaderBytes + bitmap)};
  const std::uint8_t* h = message.data();
  if (!std::equal(kMagic.begin(), kMagic.end(), h) || h[4] != kVersion)
    return Failure{"not a frame message (magic or version)"};
  if (h[5] > static_cast<std::uint8_t>(LinkCodec::Whole))
    return Failure{fmt::format("unknown codec {}", h[5])};
  const auto codec = static_cast<LinkCodec>(h[5]);
  if (get_u32(h + 8) != static_cast<std::uint32_t>(width_) ||
      get_u32(h + 12) != static_cast<std::uint32_t>(height_))
    return Failure{fmt::format("a {}x{} frame, expected {}x{}", get_u32(h + 8), get_u32(h + 12),
                               width_, height_)};
  const std::uint32_t changed = get_u32(h + 16), packed = get_u32(h + 20);
  if (message.size() != kHeaderBytes + bitmap + packed)
    return Failure{fmt::format("{} bytes, its header says {}", message.size(),
                               kHeaderBytes + bitmap + std::size_t{packed})};
  const std::uint8_t* rows = h + kHeaderBytes;
  std::uint32_t marked = 0;
  for (std::size_t i = 0; i < bitmap; ++i)
    marked += static_cast<std::uint32_t>(__builtin_popcount(rows[i]));
  if (height_ % 8 != 0 && (rows[bitmap - 1] >> (height_ % 8)) != 0)
    return Failure{"rows marked below the frame"};
  if (marked != changed)
    return Failure{fmt::format("{} rows marked changed, its header says {}", marked, changed)};
  if (codec == LinkCodec::Whole &&
      (changed != static_cast<std::uint32_t>(height_) || packed != frame_.size()))
    return Failure{fmt::format("a whole frame of {} rows in {} bytes, expected {} in {}", changed,
                               packed, height_, frame_.size())};
  return codec;
}

Status FrameDeltaDecoder::apply(const std::uint8_t* rows, std::uint32_t changed) {
  for (std::uint32_t r = 0; r < changed; ++r)
    if (block_[r * (1 + stride_)] > kSpatial)
      return Failure{fmt::format("changed row {} has mode {}", r, block_[r * (1 + stride_)])};

  const std::uint8_t* residual = block_.data();
  for (int y = 0; y < height_; ++y) {
    if (!(rows[static_cast<std::size_t>(y) / 8] & (1u << (y % 8)))) continue;
    std::uint8_t* row = frame_.data() + stride_ * static_cast<std::size_t>(y);
    const std::uint8_t* r = residual + 1;
    if (residual[0] == kTemporal) {
      for (std::size_t i = 0; i < stride_; ++i) row[i] ^= r[i];
    } else {
      for (std::size_t i = 0; i < std::min<std::size_t>(3, stride_); ++i) row[i] = r[i];
      for (std::size_t i = 3; i < stride_; ++i)
        row[i] = static_cast<std::uint8_t>(r[i] + row[i - 3]);
    }
    residual += 1 + stride_;
  }
  return {};
}

}  // namespace l2
