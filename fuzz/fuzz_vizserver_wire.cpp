// The compositing server's message decoder (docs/vizserver-protocol.md) on an arbitrary byte
// stream, taken message by message as the server takes it: header checked first, then the
// fixed part, then the size of the variable part, which is skipped, never allocated. A header
// that passes is within the bounds of its kind, and a fixed part decoded and encoded again
// gives back the bytes it came from.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <variant>

#include "dvi_link/frame_delta.hpp"
#include "fuzz_check.hpp"
#include "viz_link/wire.hpp"

namespace {

using l2::fuzz::require;
namespace viz = l2::viz;

template <class Encoded>
bool same_bytes(const Encoded& encoded, std::span<const std::uint8_t> message) {
  return std::equal(encoded.begin(), encoded.end(), message.begin());
}

// Re-encodes a fixed-size message and compares it with what was received.
bool round_trips(viz::Kind kind, std::span<const std::uint8_t> message) {
  const auto fixed = message.subspan(viz::kHeaderBytes);
  switch (kind) {
    case viz::Kind::Hello:
      return same_bytes(viz::encode(viz::decode_hello(fixed)), message);
    case viz::Kind::Welcome:
      return same_bytes(viz::encode(viz::decode_welcome(fixed)), message);
    case viz::Kind::FrameDone:
      return same_bytes(viz::encode(viz::decode_frame_done(fixed)), message);
    case viz::Kind::Swapped:
      return same_bytes(viz::encode(viz::decode_swapped(fixed)), message);
    default:
      return true;
  }
}

// One message from the front of `bytes`; how many bytes it took, 0 when the stream ends or is
// refused there (the server closes the connection).
std::size_t take_message(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < viz::kHeaderBytes) return 0;
  const auto decoded = viz::decode_header(bytes.first<viz::kHeaderBytes>());
  if (!decoded.ok()) {
    l2::fuzz::require_one_line(decoded.reason(), "a refused header has a one-line reason");
    return 0;
  }
  const viz::Header h = decoded.value();
  const std::size_t fixed = viz::fixed_bytes(h.kind);
  require(fixed <= viz::kMaxFixedBytes, "a fixed part fits the server's header buffer");
  require(h.payload_bytes >= fixed, "a payload holds its fixed part");
  if (h.kind == viz::Kind::Error) require(h.payload_bytes <= viz::kMaxErrorText, "ERROR bound");
  if (bytes.size() < viz::kHeaderBytes + fixed) return 0;
  const auto message = bytes.first(viz::kHeaderBytes + fixed);
  std::size_t variable = h.payload_bytes - fixed;
  if (h.kind == viz::Kind::Tile || h.kind == viz::Kind::TileExt) {
    const bool ext = h.kind == viz::Kind::TileExt;
    const auto fixed_part = message.subspan(viz::kHeaderBytes);
    const viz::TileHeader t = ext ? viz::decode_tile_ext(fixed_part) : viz::decode_tile(fixed_part);
    if (const l2::Status tile = viz::validate(t, h.payload_bytes); !tile.ok()) {
      l2::fuzz::require_one_line(tile.reason(), "a refused TILE has a one-line reason");
      return 0;
    }
    require(t.w >= 1 && t.w <= viz::kMaxTileSide && t.h >= 1 && t.h <= viz::kMaxTileSide,
            "a valid TILE's sides are 1..4095");
    require(t.pixel_bytes() == variable, "a valid TILE's pixels are its payload after 24 bytes");
    require(ext ? same_bytes(viz::encode_ext(t), message) : same_bytes(viz::encode(t), message),
            "a valid TILE header encodes back the same");
  } else if (h.kind == viz::Kind::TileDelta) {
    // What the server checks before it allocates the encoded part (tile_delta.hpp decodes it).
    const viz::TileHeader t = viz::decode_tile_ext(message.subspan(viz::kHeaderBytes));
    if (const l2::Status tile = viz::validate_delta(t, h.payload_bytes); !tile.ok()) {
      l2::fuzz::require_one_line(tile.reason(), "a refused TILE_DELTA has a one-line reason");
      return 0;
    }
    require(variable <= l2::max_frame_delta_bytes(static_cast<int>(t.row_bytes() / 3),
                                                  static_cast<int>(t.h)),
            "a valid TILE_DELTA's encoded part is no larger than its tile's changes can be");
    require(same_bytes(viz::encode_delta(t, variable), message),
            "a valid TILE_DELTA header encodes back the same");
  } else {
    require(h.kind == viz::Kind::Error || variable == 0, "fixed kinds have no variable part");
    require(round_trips(h.kind, message), "a fixed part encodes back to the same bytes");
  }
  const std::size_t total = viz::kHeaderBytes + fixed + variable;
  return std::min(total, bytes.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::span<const std::uint8_t> bytes(data, size);
  while (const std::size_t used = take_message(bytes)) bytes = bytes.subspan(used);
  return 0;
}
