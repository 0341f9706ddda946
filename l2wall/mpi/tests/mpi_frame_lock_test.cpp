// Frame lock under `mpirun ... l2wall run --mpi`: the coordinator's DVI path takes the frame
// stamps of the column rank's displays, so drifting clocks show mismatched refreshes and house
// sync none, as on one machine (l2wall/tests/live_run_frame_lock_test.cpp).
#include <gtest/gtest.h>

#include "frame_lock_run.hpp"
#include "mpirun_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// 3 pipeserver ranks, 1 board column, the coordinator.
FrameLockRun run_over_mpi(const std::string& name, const std::string& wall) {
  const MpirunBase base;
  WallRun run(name,
              {"--wall", (kFrameLockWalls / wall).string(), "--frames", "40", "--refresh", "0",
               "--keep", "every", "--mpi"},
              {}, false, mpirun(base, 5));
  EXPECT_TRUE(wait_mpirun(run, base, 180s).ok()) << run.output();
  return frame_lock_of(run, 40);
}

TEST(MpiFrameLock, FreeRunningClocksShowMismatchedRefreshes) {
  expect_free_running(run_over_mpi("mpi-frame-lock-free", "projectors-drifting.toml"));
}

TEST(MpiFrameLock, HouseSyncShowsNone) {
  expect_house_sync(run_over_mpi("mpi-frame-lock-house", "projectors-house-sync.toml"));
}

}  // namespace
}  // namespace l2
