// Spec §7 packing: KEY and DEPTH tiles with four-column gaps and payloads of w and 2w columns,
// sharing rows with COPY tiles. Expected columns are worked out by hand from the rules.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "display_tile.hpp"
#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

DisplayTile composited(Compositing how, int display, int dx, int dy, int w, int h,
                       std::uint32_t key = 0) {
  DisplayTile t = display_tile(display, dx, dy, w, h);
  t.compositing = how;
  t.key = key;
  return t;
}

std::string what_fails(int fb_width, const std::vector<DisplayTile>& tiles) {
  try {
    pack_tiles(1, fb_width, 10, tiles);
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "packed";
}

TEST(CompositingPack, KeyDepthAndCopyTilesShareARow) {
  // W = 40: KEY 5 wide: gap 0..3, pixels 4..8; DEPTH 3 wide: gap 9..12, colour 13..15, depth
  // 16..18; COPY 4 wide: gap 19..20, pixels 21..24; DEPTH 6 wide needs 4 + 12 = 16 columns from
  // 25: 41 > 40, so it opens row 2 (y = 3, below the 3-row KEY tile), pixels 4..9 and 10..15.
  const PipeserverPlan plan =
      pack_tiles(0, 40, 10,
                 {composited(Compositing::Key, 0, 0, 0, 5, 3, 0x00FF00),
                  composited(Compositing::Depth, 1, 0, 0, 3, 2), display_tile(2, 0, 0, 4, 1),
                  composited(Compositing::Depth, 3, 0, 0, 6, 2)});
  const int expected[4][2] = {{4, 0}, {13, 0}, {21, 0}, {4, 3}};
  ASSERT_EQ(plan.tiles.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(plan.tiles[i].fb_x, expected[i][0]) << "tile " << i;
    EXPECT_EQ(plan.tiles[i].fb_y, expected[i][1]) << "tile " << i;
  }
  ASSERT_EQ(plan.rows.size(), 2u);
  EXPECT_EQ(plan.rows[0].tile_count, 3);
  EXPECT_EQ(plan.rows[0].height, 3);
  EXPECT_EQ(plan.used_height(), 5);
}

TEST(CompositingPack, ATileEndingAtTheLastColumnStaysInTheRow) {
  // 4 + 2·8 = 20, then 20 + 4 + 16 = 40 = W: both in row 0; a COPY of 1 then needs a new row.
  const PipeserverPlan plan =
      pack_tiles(0, 40, 10,
                 {composited(Compositing::Depth, 0, 0, 0, 8, 1),
                  composited(Compositing::Key, 0, 0, 1, 16, 1), display_tile(0, 0, 2, 1, 1)});
  EXPECT_EQ(plan.tiles[1].fb_x, 24);
  EXPECT_EQ(plan.tiles[1].fb_y, 0);
  EXPECT_EQ(plan.tiles[2].fb_x, 2);
  EXPECT_EQ(plan.tiles[2].fb_y, 1);
}

TEST(CompositingPack, GapPlusPayloadWiderThanTheFramebufferIsRefused) {
  EXPECT_EQ(what_fails(40, {composited(Compositing::Depth, 4, 8, 9, 18, 1)}), "packed");
  EXPECT_EQ(what_fails(40, {composited(Compositing::Depth, 4, 8, 9, 19, 1)}),
            "pipeserver 1: tile 0 (display 4, 19x1 at 8,9, DEPTH) does not fit the 40x10 "
            "framebuffer: needs 42 columns, 2 too many");
  EXPECT_EQ(what_fails(40, {composited(Compositing::Key, 0, 0, 0, 36, 1)}), "packed");
  EXPECT_EQ(
      what_fails(40, {display_tile(0, 0, 0, 2, 1), composited(Compositing::Key, 0, 0, 0, 37, 1)}),
      "pipeserver 1: tile 1 (display 0, 37x1 at 0,0, KEY) does not fit the 40x10 "
      "framebuffer: needs 41 columns, 1 too many");
}

TEST(CompositingPack, TilesWhoseSkipOrKeyCannotBeEncodedAreRefused) {
  EXPECT_EQ(what_fails(5000, {composited(Compositing::Depth, 0, 0, 0, 2047, 1)}),
            "pipeserver 1: tile 0 (display 0, 2047x1 at 0,0, DEPTH): the SKIP below a KEY or "
            "DEPTH tile, payload + 2 wide, must be at most 4095");
  EXPECT_EQ(what_fails(5000, {composited(Compositing::Depth, 0, 0, 0, 2046, 1)}), "packed");
  EXPECT_EQ(what_fails(40, {composited(Compositing::Key, 0, 0, 0, 4, 1, 0x1000000)}),
            "pipeserver 1: tile 0 (display 0, 4x1 at 0,0, KEY): key colour must be "
            "000000..ffffff");
}

constexpr Rgb kLeftOver{7, 8, 9};  // what a renderer left: every header must be drawn over it

// Scanlines 0..rows-1 as the parser (strip_headers, independent of the packer) reads them.
std::vector<std::string> parsed_rows(const RgbImage& fb, int rows) {
  std::vector<std::string> out;
  for (int y = 0; y < rows; ++y) {
    StripErrorCounts errors;
    std::string line = std::to_string(y) + ":";
    parse_scanline(fb.row(y).data(), fb.width(), 3, errors, [&](const ParsedStrip& s) {
      line += " [" + std::to_string(s.header_x()) + "] " + to_string(s.header);
      if (s.header.op == StripOp::Ext) line += " " + to_string(s.extension);
    });
    if (errors.total() > 0) line += " errors";
    out.push_back(line);
  }
  return out;
}

TEST(CompositingPack, HeadersOfADepthTileThenSkipsOfPayloadPlusTwo) {
  // W = 24 (docs/strip-header.md §7 example): DEPTH 3x1 at gap 0 (word 2..3, colour 4..6, depth
  // 7..9), COPY 4x2 at gap 10 (pixels 12..15), END at 16. Below the DEPTH tile: SKIP of 8.
  const PipeserverPlan plan = pack_tiles(
      0, 24, 3, {composited(Compositing::Depth, 1, 5, 6, 3, 1), display_tile(2, 7, 8, 4, 2)});
  RgbImage fb(24, 3, kLeftOver);
  draw_headers(plan, true, fb);
  EXPECT_EQ(parsed_rows(fb, 2),
            (std::vector<std::string>{
                "0: [0] EXT f=1 d=1 x=5 y=6 w=3 DEPTH [10] COPY f=1 d=2 x=7 y=8 w=4",
                "1: [0] SKIP f=1 d=0 x=0 y=0 w=8 [10] COPY f=1 d=2 x=7 y=9 w=4"}));
  for (int y = 0; y < 2; ++y) {
    const std::uint8_t* end = fb.row(y).data() + 16 * 3;
    EXPECT_EQ(header_value(end, end + 3), 0u) << y;  // END, drawn over the paint
  }
  const std::uint8_t* word = fb.row(0).data() + 2 * 3;
  EXPECT_EQ(header_value(word, word + 3), 0x200000000064u);  // §7 vector: DEPTH
}

TEST(CompositingPack, KeyTileCarriesItsKeyColour) {
  const PipeserverPlan plan =
      pack_tiles(0, 12, 2, {composited(Compositing::Key, 0, 1, 2, 3, 2, 0x00FF00)});
  RgbImage fb(12, 2, kLeftOver);
  draw_headers(plan, false, fb);
  EXPECT_EQ(parsed_rows(fb, 2),
            (std::vector<std::string>{"0: [0] EXT f=0 d=0 x=1 y=2 w=3 KEY key=00ff00",
                                      "1: [0] EXT f=0 d=0 x=1 y=3 w=3 KEY key=00ff00"}));
  const std::uint8_t* word = fb.row(1).data() + 2 * 3;
  EXPECT_EQ(header_value(word, word + 3), 0x1000FF000019u);  // §7 vector: KEY 00FF00
}

TEST(CompositingPack, ClearOutsideTilesKeepsDepthPixelsAndClearsBelowTheTile) {
  // DEPTH 3x1 and COPY 4x2 as above: on scanline 1 the DEPTH tile's word and payload columns
  // (2..9) are passed over by the SKIP and cleared; its depth pixels on scanline 0 stay.
  const PipeserverPlan plan = pack_tiles(
      0, 24, 3, {composited(Compositing::Depth, 1, 5, 6, 3, 1), display_tile(2, 7, 8, 4, 2)});
  const Rgb white{255, 255, 255};
  RgbImage fb(24, 3, white);
  clear_outside_tiles(plan, fb);
  for (int x = 0; x < 24; ++x) {
    const bool row0_kept = x < 16;                        // gaps and payloads up to the END
    const bool row1_kept = x < 2 || (x >= 10 && x < 16);  // SKIP header, COPY gap and tile
    EXPECT_EQ(fb.at(x, 0), row0_kept ? white : Rgb{}) << x;
    EXPECT_EQ(fb.at(x, 1), row1_kept ? white : Rgb{}) << x;
    EXPECT_EQ(fb.at(x, 2), Rgb{}) << x;
  }
}

}  // namespace
}  // namespace l2
