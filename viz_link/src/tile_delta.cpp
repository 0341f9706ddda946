#include "viz_link/tile_delta.hpp"

#include <fmt/format.h>

#include <cstring>

namespace l2::viz {
namespace {

template <class Key>
Key key_of(const TileHeader& t) {
  return {t.display, t.dx, t.dy, t.w, t.h, static_cast<std::uint32_t>(t.how)};
}

int columns_of(const TileHeader& t) {
  return static_cast<int>(t.row_bytes() / 3);
}

// Drops the entries the frame did not use and marks the rest unused for the next.
template <class Map, class Dropped>
void sweep(Map& tiles, Dropped&& dropped) {
  for (auto it = tiles.begin(); it != tiles.end();) {
    if (!it->second.used) {
      dropped(it->second);
      it = tiles.erase(it);
    } else {
      it->second.used = false;
      ++it;
    }
  }
}

}  // namespace

std::span<const std::uint8_t> TileDeltaEncoder::encode(const TileHeader& tile,
                                                       const std::uint8_t* rgb,
                                                       std::size_t stride) {
  const Key key = key_of<Key>(tile);
  auto it = tiles_.find(key);
  if (it == tiles_.end())
    it = tiles_
             .emplace(key,
                      Entry{FrameDeltaEncoder(columns_of(tile), static_cast<int>(tile.h), codec_)})
             .first;
  it->second.used = true;
  const std::size_t row = tile.row_bytes();
  rows_.resize(row * tile.h);
  for (std::uint32_t r = 0; r < tile.h; ++r)
    std::memcpy(rows_.data() + row * r, rgb + stride * r, row);
  return it->second.encoder.encode(rows_);
}

void TileDeltaEncoder::end_frame() {
  sweep(tiles_, [](const Entry&) {});
}

Result<std::vector<std::uint8_t>> TileDeltaDecoder::decode(const TileHeader& tile,
                                                           std::span<const std::uint8_t> message) {
  const Key key = key_of<Key>(tile);
  auto it = tiles_.find(key);
  if (it == tiles_.end()) {
    const std::size_t bytes = tile.pixel_bytes();
    if (held_ + bytes > budget_)
      return Failure{
          fmt::format("a new {}x{} tile on display {} would hold {} bytes of tiles, "
                      "more than the {} allowed",
                      tile.w, tile.h, tile.display, held_ + bytes, budget_)};
    it = tiles_
             .emplace(key,
                      Entry{FrameDeltaDecoder(columns_of(tile), static_cast<int>(tile.h)), bytes})
             .first;
    held_ += bytes;
  }
  it->second.used = true;
  if (const Status s = it->second.decoder.decode(message); !s.ok())
    return Failure{fmt::format("TILE_DELTA {}x{} on display {}: {}", tile.w, tile.h, tile.display,
                               s.reason())};
  const std::span<const std::uint8_t> frame = it->second.decoder.frame();
  return std::vector<std::uint8_t>(frame.begin(), frame.end());
}

void TileDeltaDecoder::end_frame() {
  sweep(tiles_, [this](const Entry& e) { held_ -= e.bytes; });
}

}  // namespace l2::viz
