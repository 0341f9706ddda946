#include "tilelayout/survival.hpp"

#include <gtest/gtest.h>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

// Six 100x100 tiles in a row, three pipeservers of 310x100: each holds two (2 x 102 columns).
// Two left hold three each (306 columns, one row); one left holds all six, three a row: 200 rows.
constexpr const char* kSixTiles = R"([display_grid]
columns = 1
rows = 1
width = 600
height = 100
[tiling]
kind = "grid"
tile_width = 100
tile_height = 100
[pipeservers]
count = 3
framebuffer_width = 310
framebuffer_height = 100
)";

TEST(Survival, HandCountedRowsOfTiles) {
  const Wall wall = parse_wall(kSixTiles, "six.toml");
  EXPECT_EQ(survival_height(wall, 0), 100);
  EXPECT_EQ(survival_height(wall, 1), 100);
  EXPECT_EQ(survival_height(wall, 2), 200);
  EXPECT_EQ(survival_height(wall, 3), std::nullopt);  // nobody left
  const Survival s = survival(wall);
  EXPECT_EQ(s.survives, 1);
  EXPECT_EQ(survival_line(wall, s),
            "survives the loss of 1 pipeserver (framebuffers 310x100); 2: needs "
            "framebuffer_height >= 200");
  EXPECT_EQ(survival_suggestions(wall, s),
            (std::vector<std::string>{
                "framebuffer_height = 100 (at framebuffer_width = 310): survives the loss of 1 "
                "pipeserver",
                "framebuffer_height = 200 (at framebuffer_width = 310): survives the loss of 2 "
                "pipeservers"}));
}

TEST(Survival, EveryChoiceOfLostPipeserversPlans) {
  // What survival counts on is what the planner packs: every pair of the three, gone, plans at
  // the height it names, and none at one row less.
  Wall wall = parse_wall(kSixTiles, "six.toml");
  for (const std::vector<int>& gone : {std::vector<int>{0}, {1}, {2}}) {
    const TileLayout layout = plan_without(wall, gone);
    EXPECT_TRUE(layout.pipeservers[static_cast<std::size_t>(gone[0])].tiles.empty());
  }
  EXPECT_THROW(plan_without(wall, {0, 2}), LayoutError);
  wall.framebuffer_height = 200;
  for (const std::vector<int>& gone : {std::vector<int>{0, 1}, {0, 2}, {1, 2}}) {
    const TileLayout layout = plan_without(wall, gone);
    for (const PipeserverPlan& p : layout.pipeservers) {
      const bool lost = p.pipeserver == gone[0] || p.pipeserver == gone[1];
      EXPECT_EQ(p.tiles.size(), lost ? 0u : 6u);
    }
  }
  EXPECT_EQ(survival(wall).survives, 2);
  EXPECT_EQ(survival_line(wall, survival(wall)),
            "survives the loss of any 2 of its 3 pipeservers (framebuffers 310x200)");
}

TEST(Survival, DefaultWall) {
  // Three 800x600 framebuffers cannot hold four pipeservers' tiles.
  Wall wall = default_wall();
  const Survival s = survival(wall);
  EXPECT_EQ(s.survives, 0);
  EXPECT_EQ(survival_height(wall, 1), 910);
  EXPECT_EQ(survival_height(wall, 2), 1440);
  EXPECT_EQ(survival_line(wall, s),
            "survives the loss of no pipeserver (framebuffers 800x600); 1: needs "
            "framebuffer_height >= 910");
  EXPECT_EQ(survival_suggestions(wall, s),
            (std::vector<std::string>{
                "framebuffer_height = 910 (at framebuffer_width = 800): survives the loss of 1 "
                "pipeserver",
                "framebuffer_height = 1440 (at framebuffer_width = 800, and [mesh] "
                "board_max_height = 1440): survives the loss of 2 pipeservers",
                "framebuffer_width = 1280, framebuffer_height = 769: survives the loss of 2 "
                "pipeservers within the boards' 1280x1024"}));
  // Past the boards' rows, the wider framebuffer suggested instead holds two losses exactly.
  Wall wide = default_wall();
  wide.framebuffer_width = 1280;
  wide.framebuffer_height = 769;
  EXPECT_EQ(survival(wide).survives, 2);
  wide.framebuffer_height = 768;
  EXPECT_EQ(survival(wide).survives, 1);
  // The planner agrees: at 910 rows every single loss plans, at 909 none does.
  wall.framebuffer_height = 910;
  EXPECT_EQ(survival(wall).survives, 1);
  for (int gone = 0; gone < 4; ++gone) {
    const TileLayout layout = plan_without(wall, {gone});
    EXPECT_TRUE(layout.pipeservers[static_cast<std::size_t>(gone)].tiles.empty());
  }
  wall.framebuffer_height = 909;
  for (int gone = 0; gone < 4; ++gone) EXPECT_THROW(plan_without(wall, {gone}), LayoutError);
}

TEST(Survival, DefaultWallWithLargerFramebuffers) {
  // l2wall_run_survive_tests' wall: the default at 1024x768.
  Wall wall = default_wall();
  wall.framebuffer_width = 1024;
  wall.framebuffer_height = 768;
  const Survival s = survival(wall);
  EXPECT_EQ(s.survives, 1);
  EXPECT_EQ(survival_line(wall, s),
            "survives the loss of 1 pipeserver (framebuffers 1024x768); 2: needs "
            "framebuffer_height >= 812");
  for (int gone = 0; gone < 4; ++gone) {
    const TileLayout layout = plan_without(wall, {gone});
    EXPECT_TRUE(layout.pipeservers[static_cast<std::size_t>(gone)].tiles.empty());
  }
  EXPECT_THROW(plan_without(wall, {0, 1}), LayoutError);
  wall.framebuffer_height = 812;
  EXPECT_NO_THROW(plan_without(wall, {0, 1}));
}

TEST(Survival, MonitorWall) {
  // Framebuffers sized for its eight pipeservers, the boards' limit raised to match: seven need
  // more rows, past that limit too.
  const Wall wall = load_wall(L2_WALLS_DIR "/monitors-4x3.toml");
  const Survival s = survival(wall);
  EXPECT_EQ(survival_line(wall, s),
            "survives the loss of no pipeserver (framebuffers 1328x1560); 1: needs "
            "framebuffer_height >= 2048 with [mesh] board_max_height = 2048");
}

TEST(Survival, NotOfferedOnDepthWallsOrOnePipeserver) {
  const Wall depth = load_wall(L2_WALLS_DIR "/sort-last-512x384.toml");
  EXPECT_EQ(survival_line(depth, survival(depth)),
            "survives the loss of no pipeserver: a wall with [depth] or [overlay] does not "
            "balance, and only a balanced run survives a loss");
  Wall one = parse_wall(kSixTiles, "six.toml");
  one.pipeserver_count = 1;
  one.framebuffer_height = 200;
  EXPECT_EQ(survival_line(one, survival(one)),
            "survives the loss of no pipeserver: its one pipeserver has nobody to take its tiles");
}

}  // namespace
}  // namespace l2
