// A scanned-out frame sent over a network as what changed since the last frame sent to the same
// receiver, losslessly (the displays stay byte for byte): pure logic, no I/O. The DVI link over
// MPI sends frames this way (mpi_link/mpi_dvi_link).
//
// Each scanline is either unchanged (one bit) or sent as a residual, whichever of two predictions
// leaves the smaller one (the sum of its bytes taken as signed, as PNG encoders choose):
//   - temporal: XOR with the same scanline of the last frame. A still picture's rows differ only
//     in their strip headers, whose frame parity flips every frame (spec §4 rule 3): a few
//     non-zero bytes in a row of zeros.
//   - spatial: each byte minus the same channel of the pixel to its left, as PNG's Sub filter:
//     smooth shading turns into small, repeating residuals.
// The residuals of a frame are then compressed as one block (LZ4 or zstd), or sent as they are
// when that does not make them smaller. Pixels the receiver has no use for (strips of another
// board column's displays) can be sent as black: they then cost nothing after the first frame.
//
// Message (little-endian): magic "L2FD", version 1, codec, 2 reserved bytes; width, height,
// changed rows, compressed bytes (u32 each); a bitmap of changed rows (bit y%8 of byte y/8);
// the compressed block. Uncompressed, the block is, per changed row top to bottom, one mode byte
// (0 temporal, 1 spatial) and the row's width * 3 residual bytes. Codec 3 (whole): every row
// marked, and the block is the rows themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

struct ZSTD_CCtx_s;  // zstd.h's ZSTD_CCtx

namespace l2 {

// How the residual block is compressed; or Whole: no prediction, every row as it is, in one
// copy (for a receiver on the same machine, where a copy costs less than predicting).
enum class LinkCodec : std::uint8_t { Raw = 0, Lz4 = 1, Zstd = 2, Whole = 3 };

// "raw", "lz4", "zstd", "whole"; anything else is a Failure naming the choices.
Result<LinkCodec> parse_link_codec(std::string_view text);
std::string_view link_codec_name(LinkCodec codec);
// --link-codec of l2wall run and pipeserver: a codec, or "auto" (nullopt): zstd to a machine
// of its own, whole frames and tiles to a receiver on the same machine.
Result<std::optional<LinkCodec>> parse_link_choice(std::string_view text);
// That option's help, the same in every program.
std::string_view link_choice_help();

// Pixels sent as black: columns x .. x+w-1 of rows y .. y+h-1.
struct BlankRect {
  int x = 0, y = 0, w = 0, h = 0;
  bool operator==(const BlankRect&) const = default;
};

// The largest message a frame of width x height can take (every row changed, the block stored).
std::size_t max_frame_delta_bytes(int width, int height);
// A whole frame's message is this many bytes (header, bitmap) and then its rows: a sender may
// write them (write_whole_frame_prefix) before the place it scans its frame out into.
std::size_t whole_frame_prefix_bytes(int height);
void write_whole_frame_prefix(int width, int height, std::span<std::uint8_t> out);

class FrameDeltaEncoder {
 public:
  // For frames of width x height RGB pixels; the receiver starts from a black frame.
  FrameDeltaEncoder(int width, int height, LinkCodec codec);

  // The message that turns the receiver's frame into `frame` (rows of width * 3 bytes, top to
  // bottom) with `blank` black; valid until the next call. Throws std::invalid_argument when
  // `frame` is not width * height * 3 bytes.
  std::span<const std::uint8_t> encode(std::span<const std::uint8_t> frame,
                                       std::span<const BlankRect> blank = {});

 private:
  void encode_row(int y, const std::uint8_t* row);
  std::span<const std::uint8_t> encode_whole(std::span<const std::uint8_t> frame,
                                             std::span<const BlankRect> blank);

  int width_, height_;
  std::size_t stride_;
  LinkCodec codec_;
  std::vector<std::uint8_t> previous_;  // what the receiver holds
  std::vector<std::uint8_t> masked_;    // one row, blanked
  std::vector<std::uint8_t> bitmap_;
  std::vector<std::uint8_t> block_;    // mode byte + residual, per changed row
  std::vector<std::uint8_t> spatial_;  // one row's spatial residual
  std::vector<std::uint8_t> message_;
  std::uint32_t changed_ = 0;
  struct ZstdFree {
    void operator()(ZSTD_CCtx_s* context) const;
  };
  std::unique_ptr<ZSTD_CCtx_s, ZstdFree> zstd_;  // kept across frames
};

class FrameDeltaDecoder {
 public:
  FrameDeltaDecoder(int width, int height);

  // Applies `message` to the frame held. A malformed message (wrong size, magic, codec, frame
  // size, counts, or a block that does not decompress to exactly what the header says) is a
  // Failure saying what, and leaves the frame held unchanged.
  Status decode(std::span<const std::uint8_t> message);
  // Whether `message` is a well-formed whole frame (its rows follow whole_frame_prefix_bytes
  // of it), which a receiver may then use where it lies, without decode().
  Status check_whole(std::span<const std::uint8_t> message) const;
  // The frame held: black until the first message.
  std::span<const std::uint8_t> frame() const { return frame_; }

 private:
  // The header and bitmap checked; the codec, or why not.
  Result<LinkCodec> check(std::span<const std::uint8_t> message) const;
  // Applies the decompressed block of `changed` rows marked in `rows` (the bitmap).
  Status apply(const std::uint8_t* rows, std::uint32_t changed);

  int width_, height_;
  std::size_t stride_;
  std::vector<std::uint8_t> frame_;
  std::vector<std::uint8_t> block_;
};

}  // namespace l2
