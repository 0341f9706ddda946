// [displays]: clock_ppm per display or per swap group, and sync = "house".
#include <gtest/gtest.h>

#include <string>

#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

// Three displays, the first two in swap group 4, the third in group 1. Line numbers matter.
const std::string kClockWall =
    "[display_grid]\n"             // 1
    "columns = 3\n"                // 2
    "rows = 1\n"                   // 3
    "width = 100\n"                // 4
    "height = 80\n"                // 5
    "swap_groups = [4, 4, 1]\n"    // 6
    "[tiling]\n"                   // 7
    "kind = \"grid\"\n"            // 8
    "tile_width = 50\n"            // 9
    "tile_height = 40\n"           // 10
    "[pipeservers]\n"              // 11
    "count = 2\n"                  // 12
    "framebuffer_width = 300\n"    // 13
    "framebuffer_height = 200\n";  // 14

std::string clock_wall_error(const std::string& text) {
  try {
    parse_wall(text, "walls/t.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WallClocks, NoSectionModelsNothing) {
  const Wall w = parse_wall(kClockWall, "walls/t.toml");
  EXPECT_FALSE(w.frame_lock.modelled);
  EXPECT_FALSE(w.frame_lock.house_sync);
  for (const Display& d : w.displays) EXPECT_EQ(d.clock_ppm, 0);
}

TEST(WallClocks, PerDisplayFreeRunning) {
  const Wall w =
      parse_wall(kClockWall + "[displays]\nclock_ppm = [0, -1000, 250]\n", "walls/t.toml");
  EXPECT_TRUE(w.frame_lock.modelled);
  EXPECT_FALSE(w.frame_lock.house_sync);
  EXPECT_EQ(w.frame_lock.line, 15);
  EXPECT_EQ(w.displays[0].clock_ppm, 0);
  EXPECT_EQ(w.displays[1].clock_ppm, -1000);
  EXPECT_EQ(w.displays[2].clock_ppm, 250);
}

TEST(WallClocks, PerGroupInAscendingGroupNumber) {
  // Groups 1 and 4: group 1 (display 2) takes the first entry, group 4 (displays 0, 1) the second.
  const Wall w = parse_wall(kClockWall + "[displays]\nclock_ppm = [7, -30]\nsync = \"house\"\n",
                            "walls/t.toml");
  EXPECT_TRUE(w.frame_lock.house_sync);
  EXPECT_EQ(w.displays[0].clock_ppm, -30);
  EXPECT_EQ(w.displays[1].clock_ppm, -30);
  EXPECT_EQ(w.displays[2].clock_ppm, 7);
}

TEST(WallClocks, SyncAloneModelsLockedClocks) {
  const Wall w = parse_wall(kClockWall + "[displays]\nsync = \"house\"\n", "walls/t.toml");
  EXPECT_TRUE(w.frame_lock.modelled);
  EXPECT_TRUE(w.frame_lock.house_sync);
}

TEST(WallClocks, ErrorsNameLineAndField) {
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nclock_ppm = [1, 2, 3, 4]\n"),
            "walls/t.toml:16: displays.clock_ppm: needs 3 entries (one per display) or 2 (one "
            "per swap group), got 4");
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nclock_ppm = [0, 500001, 0]\n"),
            "walls/t.toml:16: displays.clock_ppm[1]: must be -500000..500000, got 500001");
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nclock_ppm = [0, 1.5, 0]\n"),
            "walls/t.toml:16: displays.clock_ppm[1]: must be an integer, got a number");
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nsync = \"genlock\"\n"),
            "walls/t.toml:16: displays.sync: must be one of free, house, got \"genlock\"");
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nclock = 3\n"),
            "walls/t.toml:16: displays.clock: unknown key (valid here: clock_ppm, sync)");
  EXPECT_EQ(clock_wall_error(kClockWall + "[displays]\nclock_ppm = 5\n"),
            "walls/t.toml:16: displays.clock_ppm: must be an array, got an integer");
}

}  // namespace
}  // namespace l2
