// Frame lock proven live (docs/wall-file.md, `[displays]`): the example walls of three
// projectors with drifting clocks, free-running and with house sync. The summary counts the
// refreshes in which the group's projectors showed different frames; frame-lock.csv has each
// projector's frame counter and frame per refresh. A wall without [displays] writes neither.
#include <gtest/gtest.h>

#include "frame_lock_run.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

FrameLockRun run_wall(const std::string& name, const std::string& wall) {
  WallRun run(name, {"--wall", (kFrameLockWalls / wall).string(), "--frames", "40", "--refresh",
                     "0", "--keep", "every"});
  const ExitStatus status = run.wait(120s);
  EXPECT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  expect_clean(run);
  return frame_lock_of(run, 40);
}

TEST(LiveRunFrameLock, FreeRunningClocksShowMismatchedRefreshes) {
  expect_free_running(run_wall("frame-lock-free", "projectors-drifting.toml"));
}

TEST(LiveRunFrameLock, HouseSyncShowsNone) {
  expect_house_sync(run_wall("frame-lock-house", "projectors-house-sync.toml"));
}

TEST(LiveRunFrameLock, WallWithoutDisplayClocksWritesNoneOfIt) {
  WallRun run("frame-lock-none", {"--frames", "3", "--refresh", "0"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_EQ(run.output().find("frame lock"), std::string::npos) << run.output();
  EXPECT_FALSE(fs::exists(run.out() / "frame-lock.csv"));
  expect_clean(run);
}

}  // namespace
}  // namespace l2
