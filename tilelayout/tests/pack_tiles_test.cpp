#include <gtest/gtest.h>

#include "display_tile.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// Expected positions worked out by hand from spec §4 rules 1 and 2 for W = 100.
std::vector<DisplayTile> five_tiles() {
  return {display_tile(0, 0, 0, 30, 10), display_tile(1, 30, 0, 40, 20),
          display_tile(2, 0, 8, 20, 5), display_tile(1, 0, 0, 96, 7), display_tile(0, 5, 6, 98, 3)};
}

TEST(PackTiles, FillsRowsLeftToRightThenStartsNewRowsBelow) {
  const PipeserverPlan plan = pack_tiles(3, 100, 50, five_tiles());
  EXPECT_EQ(plan.pipeserver, 3);
  ASSERT_EQ(plan.tiles.size(), 5u);
  const int expected[5][2] = {{2, 0}, {34, 0}, {76, 0}, {2, 20}, {2, 27}};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(plan.tiles[i].fb_x, expected[i][0]) << "tile " << i;
    EXPECT_EQ(plan.tiles[i].fb_y, expected[i][1]) << "tile " << i;
  }
  ASSERT_EQ(plan.rows.size(), 3u);
  EXPECT_EQ((std::vector<int>{plan.rows[0].y, plan.rows[0].height, plan.rows[0].first_tile,
                              plan.rows[0].tile_count}),
            (std::vector<int>{0, 20, 0, 3}));
  EXPECT_EQ((std::vector<int>{plan.rows[1].y, plan.rows[1].height, plan.rows[1].first_tile,
                              plan.rows[1].tile_count}),
            (std::vector<int>{20, 7, 3, 1}));
  EXPECT_EQ((std::vector<int>{plan.rows[2].y, plan.rows[2].height, plan.rows[2].first_tile,
                              plan.rows[2].tile_count}),
            (std::vector<int>{27, 3, 4, 1}));
  EXPECT_EQ(plan.used_height(), 30);
}

TEST(PackTiles, TileEndingExactlyAtTheEdgeStaysInTheRow) {
  // 0+2+3 = 5, 5+2+3 = 10 = W: both fit; the third starts a new row.
  const PipeserverPlan plan = pack_tiles(
      0, 10, 10,
      {display_tile(0, 0, 0, 3, 2), display_tile(0, 3, 0, 3, 4), display_tile(0, 6, 0, 3, 1)});
  EXPECT_EQ(plan.tiles[1].fb_x, 7);
  EXPECT_EQ(plan.tiles[1].fb_y, 0);
  EXPECT_EQ(plan.tiles[2].fb_x, 2);
  EXPECT_EQ(plan.tiles[2].fb_y, 4);
}

TEST(PackTiles, WidestTileIsWMinusTwo) {
  EXPECT_NO_THROW(pack_tiles(0, 100, 10, {display_tile(0, 0, 0, 98, 10)}));
  try {
    pack_tiles(2, 100, 10, {display_tile(0, 0, 0, 10, 1), display_tile(4, 8, 9, 99, 10)});
    FAIL() << "expected LayoutError";
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "pipeserver 2: tile 1 (display 4, 99x10 at 8,9) does not fit the 100x10 "
                 "framebuffer: needs 101 columns, 1 too many");
  }
}

TEST(PackTiles, TooTallNamesFirstTileCrossingTheBottomAndTheOverflow) {
  EXPECT_NO_THROW(pack_tiles(3, 100, 30, five_tiles()));
  try {
    pack_tiles(3, 100, 25, five_tiles());
    FAIL() << "expected LayoutError";
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "pipeserver 3: tile 3 (display 1, 96x7 at 0,0) does not fit the 100x25 "
                 "framebuffer: needs 30 rows, 5 too many");
  }
}

TEST(PackTiles, ExampleFromTheIssue) {
  std::vector<DisplayTile> tiles(17, display_tile(0, 0, 0, 1278, 60));
  tiles.push_back(display_tile(2, 0, 0, 400, 300));
  // 17 rows of 60 = 1020, then 300 more: 1320 rows, 296 past 1024.
  EXPECT_THROW(
      {
        try {
          pack_tiles(3, 1280, 1024, tiles);
        } catch (const LayoutError& e) {
          EXPECT_STREQ(e.what(),
                       "pipeserver 3: tile 17 (display 2, 400x300 at 0,0) does not fit the "
                       "1280x1024 framebuffer: needs 1320 rows, 296 too many");
          throw;
        }
      },
      LayoutError);
}

TEST(PackTiles, RejectsTilesHeadersCannotEncode) {
  auto message = [](const DisplayTile& t) {
    try {
      pack_tiles(1, 5000, 5000, {t});
    } catch (const LayoutError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(display_tile(64, 0, 0, 10, 10)),
            "pipeserver 1: tile 0 (display 64, 10x10 at 0,0): display must be 0..63");
  EXPECT_EQ(message(display_tile(0, 0, 0, 0, 10)),
            "pipeserver 1: tile 0 (display 0, 0x10 at 0,0): tile is empty");
  EXPECT_EQ(message(display_tile(0, 0, 0, 4096, 1)),
            "pipeserver 1: tile 0 (display 0, 4096x1 at 0,0): width must be at most 4095");
  EXPECT_EQ(message(display_tile(0, 0, 4090, 10, 7)),
            "pipeserver 1: tile 0 (display 0, 10x7 at 0,4090): display coordinates must be "
            "0..4095");
  EXPECT_EQ(message(display_tile(0, 0, 4089, 10, 7)), "no error");
}

TEST(PackTiles, EmptyListPacksNothing) {
  const PipeserverPlan plan = pack_tiles(0, 64, 64, {});
  EXPECT_TRUE(plan.tiles.empty());
  EXPECT_EQ(plan.used_height(), 0);
}

}  // namespace
}  // namespace l2
