// Tiles as what changed since their last frame (tile_delta.hpp): the pixels arrive byte for
// byte, frame after frame, through tiles that come and go; a peer cannot make the receiver hold
// more than its budget or apply a message that does not decode.
#include "viz_link/tile_delta.hpp"

#include <gtest/gtest.h>

#include <numeric>

namespace l2::viz {
namespace {

// A tile of w x h inside a framebuffer `stride` bytes wide, its pixels a pattern of `seed`.
struct Source {
  int w, h;
  std::size_t stride;
  std::vector<std::uint8_t> fb;
  Source(int w_, int h_, int seed)
      : w(w_), h(h_), stride(std::size_t(w_) * 3 + 30), fb(stride * std::size_t(h_)) {
    for (std::size_t i = 0; i < fb.size(); ++i)
      fb[i] = static_cast<std::uint8_t>(i * 7 + std::size_t(seed) * (i / 5));
  }
  std::vector<std::uint8_t> rows() const {
    std::vector<std::uint8_t> out;
    for (int r = 0; r < h; ++r)
      out.insert(out.end(), fb.begin() + static_cast<long>(stride * std::size_t(r)),
                 fb.begin() + static_cast<long>(stride * std::size_t(r) + std::size_t(w) * 3));
    return out;
  }
};

TileHeader header(std::uint32_t display, int dx, std::uint32_t w, std::uint32_t h) {
  return {0, display, dx, 0, w, h, TileKind::Copy, 0};
}

TEST(TileDelta, TilesArriveByteForByteAcrossFramesAndTilesThatComeAndGo) {
  TileDeltaEncoder encoder(LinkCodec::Zstd);
  TileDeltaDecoder decoder(1 << 20);
  // Frame by frame: which tiles are sent (display, dx) and the seed of their pixels.
  const std::vector<std::vector<std::pair<int, int>>> frames = {
      {{0, 1}, {1, 1}}, {{0, 1}, {1, 2}}, {{1, 3}}, {{0, 4}, {1, 3}}, {{0, 4}}};
  for (const auto& frame : frames) {
    for (const auto& [display, seed] : frame) {
      const Source s(20, 6, seed);
      const TileHeader t = header(static_cast<std::uint32_t>(display), 8, 20, 6);
      const auto message = encoder.encode(t, s.fb.data(), s.stride);
      const auto pixels = decoder.decode(t, message);
      ASSERT_TRUE(pixels.ok()) << pixels.reason();
      EXPECT_EQ(pixels.value(), s.rows());
    }
    encoder.end_frame();
    decoder.end_frame();
  }
}

TEST(TileDelta, AnUnchangedTileCostsItsHeader) {
  TileDeltaEncoder encoder(LinkCodec::Lz4);
  const Source s(64, 16, 9);
  const TileHeader t = header(0, 0, 64, 16);
  (void)encoder.encode(t, s.fb.data(), s.stride);
  encoder.end_frame();
  EXPECT_EQ(encoder.encode(t, s.fb.data(), s.stride).size(), 24u + 2u);  // header and bitmap
}

TEST(TileDelta, ANewTilePastTheBudgetIsRefused) {
  TileDeltaEncoder encoder(LinkCodec::Raw);
  TileDeltaDecoder decoder(2 * 10 * 10 * 3);  // two 10x10 tiles
  const Source s(10, 10, 1);
  for (int dx : {0, 10}) {
    const TileHeader t = header(0, dx, 10, 10);
    ASSERT_TRUE(decoder.decode(t, encoder.encode(t, s.fb.data(), s.stride)).ok());
  }
  const TileHeader third = header(0, 20, 10, 10);
  EXPECT_EQ(decoder.decode(third, encoder.encode(third, s.fb.data(), s.stride)).reason(),
            "a new 10x10 tile on display 0 would hold 900 bytes of tiles, more than the 600 "
            "allowed");
  // A frame later the tiles it did not carry are forgotten, and there is room again.
  decoder.end_frame();
  decoder.end_frame();
  EXPECT_TRUE(
      decoder.decode(third, TileDeltaEncoder(LinkCodec::Raw).encode(third, s.fb.data(), s.stride))
          .ok());
}

TEST(TileDelta, AMessageThatDoesNotDecodeIsRefused) {
  TileDeltaDecoder decoder(1 << 20);
  const std::vector<std::uint8_t> garbage(40, 0xAB);
  EXPECT_EQ(decoder.decode(header(2, 0, 8, 8), garbage).reason(),
            "TILE_DELTA 8x8 on display 2: not a frame message (magic or version)");
}

}  // namespace
}  // namespace l2::viz
