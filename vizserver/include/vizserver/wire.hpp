// The visualization-server wire format (docs/vizserver-protocol.md): what pipeservers and the
// compositing server say to each other over TCP. Pure encoding and validation, no I/O, so every
// rule about what a peer may send is tested without sockets.
//
// Every message = a 12-byte header (magic, version, kind, payload length; little-endian) and a
// payload. A payload has a fixed part whose size depends on the kind, and for TILE and ERROR a
// variable part (pixels, text) whose size follows from the fixed part.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>

#include "vizserver/run_token.hpp"

namespace l2::viz {

inline constexpr std::uint32_t kMagic = 0x5A56324C;  // bytes "L2VZ" on the wire
inline constexpr std::uint16_t kVersion = 2;         // 2: HELLO carries the run token
inline constexpr std::size_t kHeaderBytes = 12;
inline constexpr int kMaxTileSide = 4095;  // the 12-bit width limit of a strip header (spec §2)
inline constexpr std::size_t kMaxErrorText = 1024;
inline constexpr std::size_t kMaxFixedBytes = 32;  // the largest fixed part (TILE_EXT)

enum class Kind : std::uint16_t {
  Hello = 1,      // pipeserver -> server: who I am
  Welcome = 2,    // server -> pipeserver: accepted
  Tile = 3,       // pipeserver -> server: one rectangle of one display, RGB rows top to bottom
  FrameDone = 4,  // pipeserver -> server: my part of this frame is complete
  Swapped = 5,    // server -> every pipeserver: this frame is on the displays
  Error = 6,      // either way: why the sender is closing the connection
  TileExt = 7,    // pipeserver -> server: a KEY or DEPTH tile (spec §7), composited
};

// How a tile is composited (spec §7), as TILE_EXT carries it; a TILE is Copy.
enum class TileKind : std::uint32_t { Copy = 0, Key = 1, Depth = 2 };

struct Header {
  Kind kind{};
  std::uint32_t payload_bytes = 0;
};

struct Hello {
  std::uint32_t server_id = 0;
  std::uint32_t display_count = 0;
  RunToken token{};  // the run's token (run_token.hpp); all zero when the run has none
};

struct Welcome {
  std::uint32_t server_id = 0;
  std::uint32_t display_count = 0;
  std::uint32_t server_count = 0;
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
  std::uint32_t server_id = 0;
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
std::array<std::uint8_t, kHeaderBytes + 12> encode(const FrameDone& m);
std::array<std::uint8_t, kHeaderBytes + 4> encode(const Swapped& m);
std::array<std::uint8_t, kHeaderBytes> encode_error_header(std::size_t text_bytes);

// Checks magic, version, kind and that the length is possible for the kind (exact for fixed
// kinds, bounded for TILE and ERROR) before anyone allocates for it. Returns the header or a
// one-line reason ("bad magic 0x47455420 (not a vizserver peer?)").
std::variant<Header, std::string> decode_header(std::span<const std::uint8_t, kHeaderBytes> bytes);

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
std::optional<std::string> validate(const TileHeader& t, std::uint32_t payload_bytes);

// Little-endian helpers, exposed for tests that forge messages byte by byte.
void put_u16(std::uint8_t* p, std::uint16_t v);
void put_u32(std::uint8_t* p, std::uint32_t v);
std::uint16_t get_u16(const std::uint8_t* p);
std::uint32_t get_u32(const std::uint8_t* p);

// The 12-byte header every message of both vizserver protocols starts with (magic, version,
// kind, payload length); the tile protocol and the display stream differ only in their kinds.
void put_message_header(std::uint8_t* p, std::uint16_t kind, std::size_t payload_bytes);

}  // namespace l2::viz
