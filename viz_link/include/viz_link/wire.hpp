// The viz path's wire format (docs/vizserver-protocol.md): what pipeservers and the
// compositing server say to each other over TCP. Pure encoding and validation, no I/O, so every
// rule about what a peer may send is tested without sockets.
//
// Every message = a 12-byte header (magic, version, kind, payload length; little-endian) and a
// payload. A payload has a fixed part whose size depends on the kind, and for TILE, DISPLAY and
// ERROR a variable part (pixels, text) whose size follows from the fixed part. Both protocols
// (pipeservers' tiles here, the display stream in display_stream.hpp) share the header, its
// kinds and MessageHead, the one reader of it.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include "base/little_endian.hpp"
#include "base/result.hpp"
#include "viz_link/run_token.hpp"

namespace l2::viz {

// The clock of every deadline on the viz path's sockets (base/socket.hpp).
using Clock = std::chrono::steady_clock;

inline constexpr std::uint32_t kMagic = 0x5A56324C;  // bytes "L2VZ" on the wire
inline constexpr std::uint16_t kVersion = 2;         // 2: HELLO carries the run token
inline constexpr std::size_t kHeaderBytes = 12;
inline constexpr int kMaxTileSide = 4095;  // the 12-bit width limit of a strip header (spec §2)
inline constexpr std::size_t kMaxErrorText = 1024;
inline constexpr int kMaxDisplaySide = 16384;      // the vizserver's --displays limit
inline constexpr std::size_t kMaxFixedBytes = 32;  // the largest fixed part (TILE_EXT)

enum class Kind : std::uint16_t {
  Hello = 1,       // pipeserver -> server: who I am
  Welcome = 2,     // server -> pipeserver: accepted
  Tile = 3,        // pipeserver -> server: one rectangle of one display, RGB rows top to bottom
  FrameDone = 4,   // pipeserver -> server: my part of this frame is complete
  Swapped = 5,     // server -> every pipeserver: this frame is on the displays
  Error = 6,       // either way, both protocols: why the sender is closing the connection
  TileExt = 7,     // pipeserver -> server: a KEY or DEPTH tile (spec §7), composited
  TileDelta = 8,   // pipeserver -> server: any tile, as what changed since its last frame
  Listening = 16,  // display stream (display_stream.hpp) from here on
  Display = 17,
  Shown = 18,
  Lost = 19,  // watcher -> server: a pipeserver is gone, frames no longer wait for it
};

// How a tile is composited (spec §7), as TILE_EXT carries it; a TILE is Copy.
enum class TileKind : std::uint32_t { Copy = 0, Key = 1, Depth = 2 };

// Which conversation a reader is in: each refuses the other's kinds.
enum class Protocol { Tiles, DisplayStream };

struct Header {
  Kind kind{};
  std::uint32_t payload_bytes = 0;
};

struct Hello {
  std::uint32_t pipeserver_id = 0;
  std::uint32_t display_count = 0;
  RunToken token{};  // the run's token (run_token.hpp); all zero when the run has none
};

struct Welcome {
  std::uint32_t pipeserver_id = 0;
  std::uint32_t display_count = 0;
  std::uint32_t pipeserver_count = 0;
};

// A tile's placement. dx, dy are signed so a tile hanging off the top-left edge is expressible
// (and clipped) rather than unrepresentable.
// KEY and DEPTH tiles go as TILE_EXT: for DEPTH every row is w colour pixels and then w depth
// pixels (D = R<<16 | G<<8 | B), as in the pipeserver's framebuffer.
struct TileHeader {
  std::uint32_t frame = 0;
  std::uint32_t display = 0;
  std::int32_t dx = 0, dy = 0;
  std::uint32_t w = 0, h = 0;
  TileKind how = TileKind::Copy;
  std::uint32_t key = 0;  // Key: the key colour, R<<16 | G<<8 | B
  std::size_t row_bytes() const { return std::size_t{w} * 3 * (how == TileKind::Depth ? 2 : 1); }
  std::size_t pixel_bytes() const { return row_bytes() * h; }
  std::size_t fixed_size() const { return how == TileKind::Copy ? 24 : 32; }
};

struct FrameDone {
  std::uint32_t pipeserver_id = 0;
  std::uint32_t frame = 0;
  std::uint32_t tile_count = 0;
};

struct Swapped {
  std::uint32_t frame = 0;
};

// Size of the fixed part of each kind's payload.
std::size_t fixed_bytes(Kind kind);
const char* kind_name(Kind kind);

// Encoders: header + fixed part, ready to send. TILE pixels and ERROR text follow separately.
std::array<std::uint8_t, kHeaderBytes + 24> encode(const Hello& m);
std::array<std::uint8_t, kHeaderBytes + 12> encode(const Welcome& m);
std::array<std::uint8_t, kHeaderBytes + 24> encode(const TileHeader& m);      // a TILE (Copy)
std::array<std::uint8_t, kHeaderBytes + 32> encode_ext(const TileHeader& m);  // TILE_EXT
// TILE_DELTA: TILE_EXT's fixed part (any kind, Copy too), then `encoded_bytes` of a frame
// delta message (tile_delta.hpp).
std::array<std::uint8_t, kHeaderBytes + 32> encode_delta(const TileHeader& m,
                                                         std::size_t encoded_bytes);
std::array<std::uint8_t, kHeaderBytes + 12> encode(const FrameDone& m);
std::array<std::uint8_t, kHeaderBytes + 4> encode(const Swapped& m);
std::array<std::uint8_t, kHeaderBytes> encode_error_header(std::size_t text_bytes);

// Checks magic, version, a kind of `protocol` and that the length is possible for the kind
// (exact for fixed kinds, bounded for TILE, DISPLAY and ERROR) before anyone allocates for it.
// Returns the header or a one-line reason ("bad magic 0x47455420 (not a vizserver peer?)").
Result<Header> decode_header(std::span<const std::uint8_t, kHeaderBytes> bytes,
                             Protocol protocol = Protocol::Tiles);

// The start of one message as its bytes arrive, for every reader of both protocols: the
// header, checked as soon as it is complete (before anything is allocated for the message),
// then the fixed part of its kind. The variable part is the reader's: it goes straight into
// its final buffer.
class MessageHead {
 public:
  explicit MessageHead(Protocol protocol) : protocol_(protocol) {}

  // Where the next bytes go; empty once header and fixed part are in.
  std::span<std::uint8_t> space() { return {bytes_.data() + got_, need_ - got_}; }
  // Counts `n` bytes received into space(). Fails when they complete a header that is bad.
  Status received(std::size_t n);
  bool has_header() const { return header_.has_value(); }
  const Header& header() const { return *header_; }
  bool complete() const { return header_ && got_ == need_; }
  std::span<const std::uint8_t> fixed() const {
    return {bytes_.data() + kHeaderBytes, need_ - kHeaderBytes};
  }
  std::size_t bytes_got() const { return got_; }
  std::size_t bytes_needed() const { return need_; }  // so far: the header, then its fixed part
  void clear();                                       // ready for the next message

 private:
  Protocol protocol_;
  std::array<std::uint8_t, kHeaderBytes + kMaxFixedBytes> bytes_{};
  std::size_t got_ = 0, need_ = kHeaderBytes;
  std::optional<Header> header_;
};

// Decode fixed parts (sizes already checked by decode_header). Values are checked by
// validate(): a TILE whose payload length does not match w*h*3 (TILE_EXT: its pixel bytes),
// whose sides are 0 or over kMaxTileSide, or a TILE_EXT of another kind than KEY or DEPTH, a
// key above FFFFFF or a DEPTH with a key, is an error.
Hello decode_hello(std::span<const std::uint8_t> fixed);
Welcome decode_welcome(std::span<const std::uint8_t> fixed);
TileHeader decode_tile(std::span<const std::uint8_t> fixed);
TileHeader decode_tile_ext(std::span<const std::uint8_t> fixed);
FrameDone decode_frame_done(std::span<const std::uint8_t> fixed);
Swapped decode_swapped(std::span<const std::uint8_t> fixed);
Status validate(const TileHeader& t, std::uint32_t payload_bytes);
// A TILE_DELTA's: the tile as validate() checks it, and an encoded part no larger than the
// tile's changes can be (max_frame_delta_bytes), checked before anything is allocated.
Status validate_delta(const TileHeader& t, std::uint32_t payload_bytes);

// Writes one message: its header, then the fields of its fixed part of `Fixed` bytes in the
// order they travel, each after the last, so that no encoder counts an offset by hand. The
// payload length counts `extra` bytes (pixels, text) the sender sends after the fixed part.
// A field past the fixed part, or a fixed part left short at done(), is a bug in the encoder:
// std::logic_error.
//
//   MessageWriter<4> w(Kind::Swapped);
//   const auto bytes = w.u32(frame).done();
template <std::size_t Fixed>
class MessageWriter {
 public:
  using Bytes = std::array<std::uint8_t, kHeaderBytes + Fixed>;

  explicit MessageWriter(Kind kind, std::size_t extra = 0) {
    u32(kMagic).u16(kVersion).u16(static_cast<std::uint16_t>(kind));
    u32(static_cast<std::uint32_t>(Fixed + extra));
  }
  MessageWriter& u16(std::uint16_t v) {
    put_u16(take(2), v);
    return *this;
  }
  MessageWriter& u32(std::uint32_t v) {
    put_u32(take(4), v);
    return *this;
  }
  MessageWriter& bytes(std::span<const std::uint8_t> b) {
    std::copy(b.begin(), b.end(), take(b.size()));
    return *this;
  }
  Bytes done() const {
    if (at_ != out_.size()) throw std::logic_error("viz message: fixed part written short");
    return out_;
  }

 private:
  std::uint8_t* take(std::size_t n) {
    if (out_.size() - at_ < n) throw std::logic_error("viz message: field past the fixed part");
    std::uint8_t* at = out_.data() + at_;
    at_ += n;
    return at;
  }

  Bytes out_{};
  std::size_t at_ = 0;
};

// Reads the fields of a received fixed part in the order they travel, the decoders' side of
// MessageWriter. The caller has checked the fixed part's size (decode_header); a field past it
// is a bug in the decoder: std::logic_error.
class FieldReader {
 public:
  explicit FieldReader(std::span<const std::uint8_t> fixed) : fixed_(fixed) {}
  std::uint32_t u32() { return get_u32(take(4).data()); }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::span<const std::uint8_t> bytes(std::size_t n) { return take(n); }

 private:
  std::span<const std::uint8_t> take(std::size_t n) {
    if (fixed_.size() - at_ < n) throw std::logic_error("viz message: field past the fixed part");
    const std::span<const std::uint8_t> field = fixed_.subspan(at_, n);
    at_ += n;
    return field;
  }

  std::span<const std::uint8_t> fixed_;
  std::size_t at_ = 0;
};

}  // namespace l2::viz
