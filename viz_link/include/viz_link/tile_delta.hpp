// Tiles over a network as what changed since the same tile's last frame: each tile (its display,
// place, size and kind) is a small frame of its own for frame_delta.hpp, so a tile that did not
// change costs a header, and one that did is predicted and compressed. Both ends keep one
// encoder or decoder per tile and forget, at the end of every frame, the tiles that frame did
// not carry, so they stay in step with no message about it; a balanced run's moving tiles start
// afresh from black. Pure logic: the TCP sender, the compositing server and the MPI columns
// call it.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <tuple>
#include <vector>

#include "base/result.hpp"
#include "dvi_link/frame_delta.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz {

class TileDeltaEncoder {
 public:
  explicit TileDeltaEncoder(LinkCodec codec) : codec_(codec) {}
  // The message for `tile`'s pixels: h rows of row_bytes() at rgb + r * stride. Valid until the
  // next call.
  std::span<const std::uint8_t> encode(const TileHeader& tile, const std::uint8_t* rgb,
                                       std::size_t stride);
  // The frame's tiles are all encoded: those it did not carry are forgotten.
  void end_frame();

 private:
  using Key = std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::uint32_t, std::uint32_t,
                         std::uint32_t>;
  struct Entry {
    FrameDeltaEncoder encoder;
    bool used = true;
  };
  LinkCodec codec_;
  std::map<Key, Entry> tiles_;
  std::vector<std::uint8_t> rows_;  // a tile's rows, gathered
};

class TileDeltaDecoder {
 public:
  // `budget`: the most bytes the tiles held may take (a peer announcing ever more tiles would
  // otherwise make this side hold them all).
  explicit TileDeltaDecoder(std::size_t budget) : budget_(budget) {}
  // The pixels of `tile` (h rows of row_bytes()) from `message`; a Failure for a message that
  // does not decode, or a new tile past the budget.
  Result<std::vector<std::uint8_t>> decode(const TileHeader& tile,
                                           std::span<const std::uint8_t> message);
  void end_frame();

 private:
  using Key = std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::uint32_t, std::uint32_t,
                         std::uint32_t>;
  struct Entry {
    FrameDeltaDecoder decoder;
    std::size_t bytes = 0;
    bool used = true;
  };
  std::size_t budget_;
  std::size_t held_ = 0;
  std::map<Key, Entry> tiles_;
};

}  // namespace l2::viz
