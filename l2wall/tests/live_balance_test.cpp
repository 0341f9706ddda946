// The balance coordinator's summary after a lost pipeserver, without processes: what it counts
// stale, and the loss it refuses.
#include "l2wall/live_balance.hpp"

#include <gtest/gtest.h>

#include <string>

#include "l2wall/run_fault.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr const char* kKilled =
    "pipeserver 1 (pid 4242) killed by signal 9 (Killed) while rendering frame 101";

Wall surviving_wall(int framebuffer_height) {
  Wall wall = default_wall();
  wall.framebuffer_height = framebuffer_height;
  wall.balance.mode = BalanceMode::Strips;
  wall.balance.survive_host_loss = true;
  return wall;
}

// A run of 400 frames that ended at frame 150, before a layout without the lost pipeserver:
// frames 150..399 were never rendered, so they are not stale.
TEST(LiveBalance, OnlyFramesShownAreStale) {
  const Wall wall = surviving_wall(910);  // three framebuffers hold the four's tiles
  LiveBalance b(wall, balance_settings(wall), plan_layout(wall), 400);
  ASSERT_TRUE(b.lose(1, 101, kKilled, 3.2));
  b.note_late(101);
  b.note_late(102);
  b.note_late(140);
  EXPECT_EQ(b.summary(150),
            "balance strips: 1 layouts (from frames 0), strips routed per layout: 0\n"
            "balance: 0 of 0 group swaps showed frames of two layouts\n"
            "balance: lost pipeserver 1 (pid 4242) killed by signal 9 (Killed) while rendering "
            "frame 101, 3.20 s into the run; the run ended before a layout without it; 49 frames "
            "stale (shown incomplete or late): 101-149 (late: 101-102, 140)\n");
  EXPECT_NE(b.summary(101).find("; 0 frames stale (shown incomplete or late)\n"),
            std::string::npos);
}

// The default wall's three framebuffers cannot hold four pipeservers' tiles: the loss is refused
// at once, in one line, not survived for a frame.
TEST(LiveBalance, ALossTheOthersCannotHoldEndsTheRun) {
  const Wall wall = surviving_wall(600);
  LiveBalance b(wall, balance_settings(wall), plan_layout(wall), 400);
  try {
    b.lose(1, 101, kKilled, 3.2);
    FAIL();
  } catch (const RunFault& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind(
            std::string(kKilled) + ", and the run cannot go on without it: the other pipeservers' "
                                   "framebuffers cannot hold pipeserver 1's tiles: ",
            0),
        0u)
        << e.what();
  }
  EXPECT_EQ(b.summary(150).find("lost"), std::string::npos);
}

// Whether balancing paid, in the medians: the balanced layout's slowest render against the
// wall's own layout's predicted at the same tile costs.
TEST(LiveBalance, SaysWhetherBalancingPaid) {
  EXPECT_EQ(balance_paid_line({}, {}), "");
  EXPECT_EQ(balance_paid_line({10, 12, 11}, {18, 19.5, 17}),
            "balance: paid in render time: the slowest pipeserver took 11.0 ms a frame (median); "
            "the wall's own layout, 18.0 ms at the same costs (1.64x)\n");
  EXPECT_EQ(balance_paid_line({20, 20}, {18, 18}),
            "balance: lost in render time: the slowest pipeserver took 20.0 ms a frame (median); "
            "the wall's own layout, 18.0 ms at the same costs (0.90x)\n");
  EXPECT_EQ(balance_paid_line({20}, {20.5}).rfind("balance: no gain in render time: ", 0), 0u);
}

// The frame's render work, every pipeserver's summed: balancing that splits the costly part
// draws its geometry in more tiles, and where pipeservers share cores that work is the frame.
TEST(LiveBalance, SaysWhatBalancingCostInWork) {
  EXPECT_EQ(balance_work_line({}, {}), "");
  EXPECT_EQ(balance_work_line({70, 72, 69}, {41, 40, 43}),
            "balance: render work 70.0 ms a frame (median), the wall's own layout 41.0 ms at the "
            "same costs (1.71x the work); where pipeservers share cores the work, not the slowest "
            "pipeserver, sets the frame rate\n");
  EXPECT_EQ(balance_work_line({40}, {40}),
            "balance: render work 40.0 ms a frame (median), the wall's own layout 40.0 ms at the "
            "same costs (1.00x the work)\n");
}

}  // namespace
}  // namespace l2
