#include "viz_link/wire.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "dvi_link/frame_delta.hpp"

namespace l2::viz {
namespace {

constexpr std::size_t kMaxTilePayload =
    24 + std::size_t{kMaxTileSide} * kMaxTileSide * 3;  // about 48 MiB: one 4095x4095 tile
constexpr std::size_t kMaxTileExtPayload =
    32 + std::size_t{kMaxTileSide} * kMaxTileSide * 6;  // a 4095x4095 DEPTH tile
const std::size_t kMaxTileDeltaPayload = 32 + max_frame_delta_bytes(kMaxTileSide * 2, kMaxTileSide);
constexpr std::size_t kMaxDisplayPayload =
    16 + std::size_t{kMaxDisplaySide} * kMaxDisplaySide * 3;  // 768 MiB: fits the u32 length

bool of_protocol(std::uint16_t k, Protocol protocol) {
  if (protocol == Protocol::Tiles) return k >= 1 && k <= 8;
  return k == 6 || (k >= 16 && k <= 19);
}

// A refused kind, in the words each protocol's readers have always used.
std::string foreign_kind(std::uint16_t k, Protocol protocol) {
  if (protocol == Protocol::Tiles) return fmt::format("unknown message kind {}", k);
  return fmt::format("message kind {} is not one of the display stream", k);
}

std::size_t max_payload(Kind kind) {
  switch (kind) {
    case Kind::Tile:
      return kMaxTilePayload;
    case Kind::TileExt:
      return kMaxTileExtPayload;
    case Kind::TileDelta:
      return kMaxTileDeltaPayload;
    case Kind::Display:
      return kMaxDisplayPayload;
    case Kind::Error:
      return kMaxErrorText;
    default:
      return fixed_bytes(kind);
  }
}

}  // namespace

std::size_t fixed_bytes(Kind kind) {
  switch (kind) {
    case Kind::Hello:
      return 24;
    case Kind::Welcome:
      return 12;
    case Kind::Tile:
      return 24;
    case Kind::FrameDone:
      return 12;
    case Kind::Swapped:
      return 4;
    case Kind::Error:
      return 0;
    case Kind::TileExt:
    case Kind::TileDelta:
      return 32;
    case Kind::Listening:
      return 12;
    case Kind::Display:
      return 16;
    case Kind::Shown:
      return 20;
    case Kind::Lost:
      return 4;
  }
  return 0;
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Hello:
      return "HELLO";
    case Kind::Welcome:
      return "WELCOME";
    case Kind::Tile:
      return "TILE";
    case Kind::FrameDone:
      return "FRAME_DONE";
    case Kind::Swapped:
      return "SWAPPED";
    case Kind::Error:
      return "ERROR";
    case Kind::TileExt:
      return "TILE_EXT";
    case Kind::TileDelta:
      return "TILE_DELTA";
    case Kind::Listening:
      return "LISTENING";
    case Kind::Display:
      return "DISPLAY";
    case Kind::Shown:
      return "SHOWN";
    case Kind::Lost:
      return "LOST";
  }
  return "?";
}

std::array<std::uint8_t, kHeaderBytes + 24> encode(const Hello& m) {
  MessageWriter<24> w(Kind::Hello);
  return w.u32(m.pipeserver_id).u32(m.display_count).bytes(m.token).done();
}

std::array<std::uint8_t, kHeaderBytes + 12> encode(const Welcome& m) {
  MessageWriter<12> w(Kind::Welcome);
  return w.u32(m.pipeserver_id).u32(m.display_count).u32(m.pipeserver_count).done();
}

namespace {

// TILE's fixed part, which TILE_EXT and TILE_DELTA begin with.
template <std::size_t Fixed>
MessageWriter<Fixed>& tile_fields(MessageWriter<Fixed>& w, const TileHeader& m) {
  return w.u32(m.frame)
      .u32(m.display)
      .u32(static_cast<std::uint32_t>(m.dx))
      .u32(static_cast<std::uint32_t>(m.dy))
      .u32(m.w)
      .u32(m.h);
}

// TILE_EXT's fixed part, which TILE_DELTA shares.
MessageWriter<32>& tile_ext_fields(MessageWriter<32>& w, const TileHeader& m) {
  return tile_fields(w, m).u32(static_cast<std::uint32_t>(m.how)).u32(m.key);
}

}  // namespace

std::array<std::uint8_t, kHeaderBytes + 24> encode(const TileHeader& m) {
  MessageWriter<24> w(Kind::Tile, m.pixel_bytes());
  return tile_fields(w, m).done();
}

std::array<std::uint8_t, kHeaderBytes + 32> encode_ext(const TileHeader& m) {
  MessageWriter<32> w(Kind::TileExt, m.pixel_bytes());
  return tile_ext_fields(w, m).done();
}

std::array<std::uint8_t, kHeaderBytes + 32> encode_delta(const TileHeader& m,
                                                         std::size_t encoded_bytes) {
  MessageWriter<32> w(Kind::TileDelta, encoded_bytes);
  return tile_ext_fields(w, m).done();
}

std::array<std::uint8_t, kHeaderBytes + 12> encode(const FrameDone& m) {
  MessageWriter<12> w(Kind::FrameDone);
  return w.u32(m.pipeserver_id).u32(m.frame).u32(m.tile_count).done();
}

std::array<std::uint8_t, kHeaderBytes + 4> encode(const Swapped& m) {
  MessageWriter<4> w(Kind::Swapped);
  return w.u32(m.frame).done();
}

std::array<std::uint8_t, kHeaderBytes> encode_error_header(std::size_t text_bytes) {
  return MessageWriter<0>(Kind::Error, std::min(text_bytes, kMaxErrorText)).done();
}

Result<Header> decode_header(std::span<const std::uint8_t, kHeaderBytes> b, Protocol protocol) {
  const std::uint32_t magic = get_u32(b.data());
  if (magic != kMagic) {
    return Failure{
        fmt::format("bad magic 0x{:08x}, expected 0x{:08x} ({})", magic, kMagic,
                    protocol == Protocol::Tiles ? "not a vizserver peer?" : "not a vizserver?")};
  }
  const std::uint16_t version = get_u16(b.data() + 4);
  if (version != kVersion) {
    return Failure{fmt::format("protocol version {}, this build speaks {}", version, kVersion)};
  }
  const std::uint16_t raw_kind = get_u16(b.data() + 6);
  if (!of_protocol(raw_kind, protocol)) return Failure{foreign_kind(raw_kind, protocol)};
  const Header h{static_cast<Kind>(raw_kind), get_u32(b.data() + 8)};
  const std::size_t fixed = fixed_bytes(h.kind);
  const std::size_t max = max_payload(h.kind);
  if (h.payload_bytes < fixed || h.payload_bytes > max) {
    return Failure{fmt::format("{} payload of {} bytes, allowed {}..{}", kind_name(h.kind),
                               h.payload_bytes, fixed, max)};
  }
  return h;
}

Status MessageHead::received(std::size_t n) {
  got_ += n;
  if (header_ || got_ < kHeaderBytes) return {};
  Result<Header> decoded = decode_header(
      std::span<const std::uint8_t, kHeaderBytes>(bytes_.data(), kHeaderBytes), protocol_);
  if (!decoded.ok()) return Failure{decoded.reason()};
  header_ = *decoded;
  need_ = kHeaderBytes + fixed_bytes(header_->kind);
  return {};
}

void MessageHead::clear() {
  got_ = 0;
  need_ = kHeaderBytes;
  header_.reset();
}

Hello decode_hello(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  Hello h{r.u32(), r.u32(), {}};
  const std::span<const std::uint8_t> token = r.bytes(kTokenBytes);
  std::copy(token.begin(), token.end(), h.token.begin());
  return h;
}
Welcome decode_welcome(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  Welcome w;
  w.pipeserver_id = r.u32();
  w.display_count = r.u32();
  w.pipeserver_count = r.u32();
  return w;
}

namespace {

// TILE's fixed part, which TILE_EXT begins with.
TileHeader tile_fields(FieldReader& r) {
  TileHeader t;
  t.frame = r.u32();
  t.display = r.u32();
  t.dx = r.i32();
  t.dy = r.i32();
  t.w = r.u32();
  t.h = r.u32();
  return t;
}

}  // namespace

TileHeader decode_tile(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  return tile_fields(r);
}
TileHeader decode_tile_ext(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  TileHeader t = tile_fields(r);
  t.how = static_cast<TileKind>(r.u32());
  t.key = r.u32();
  return t;
}
FrameDone decode_frame_done(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  FrameDone d;
  d.pipeserver_id = r.u32();
  d.frame = r.u32();
  d.tile_count = r.u32();
  return d;
}
Swapped decode_swapped(std::span<const std::uint8_t> f) {
  FieldReader r(f);
  return {r.u32()};
}

Status validate(const TileHeader& t, std::uint32_t payload_bytes) {
  if (t.w < 1 || t.w > kMaxTileSide || t.h < 1 || t.h > kMaxTileSide) {
    return Failure{
        fmt::format("TILE of {}x{} pixels, each side must be 1..{}", t.w, t.h, kMaxTileSide)};
  }
  const bool key = t.how == TileKind::Key, depth = t.how == TileKind::Depth;
  if (t.how != TileKind::Copy && !key && !depth) {
    return Failure{fmt::format("TILE_EXT of kind {}, expected 1 (KEY) or 2 (DEPTH)",
                               static_cast<std::uint32_t>(t.how))};
  }
  if (t.key > 0xFFFFFF || (depth && t.key != 0)) {
    return Failure{fmt::format("TILE_EXT {} with key {:x}, allowed {}", key ? "KEY" : "DEPTH",
                               t.key, key ? "0..ffffff" : "0 only")};
  }
  if (payload_bytes != t.fixed_size() + t.pixel_bytes()) {
    return Failure{fmt::format("{} {}x{} needs a payload of {} bytes, header says {}",
                               t.how == TileKind::Copy ? "TILE" : "TILE_EXT", t.w, t.h,
                               t.fixed_size() + t.pixel_bytes(), payload_bytes)};
  }
  return {};
}

Status validate_delta(const TileHeader& t, std::uint32_t payload_bytes) {
  // The tile's own checks, as if it came whole.
  if (const Status tile = validate(t, static_cast<std::uint32_t>(t.fixed_size() + t.pixel_bytes()));
      !tile.ok())
    return tile;
  const std::size_t most =
      32 + max_frame_delta_bytes(static_cast<int>(t.row_bytes() / 3), static_cast<int>(t.h));
  if (payload_bytes < 32 || payload_bytes > most)
    return Failure{fmt::format("TILE_DELTA {}x{} with a payload of {} bytes, allowed 32..{}", t.w,
                               t.h, payload_bytes, most)};
  return {};
}

}  // namespace l2::viz
