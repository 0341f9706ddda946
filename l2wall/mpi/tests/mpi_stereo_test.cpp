// An active stereo wall under `mpirun ... l2wall run --mpi`: the pipeserver ranks render eye
// frames as the pipeserver children of a one-machine run do, the column routes them, and the
// coordinator's DVI path shows each frame's two eyes as a pair, alternating every refresh, and
// checks it from the stamps the column reads.
// Both paths' displays equal the one-machine run's byte for byte, stamps included. A packed wall
// the same.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "active_stereo_summary.hpp"
#include "mpirun_run.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// A run of example wall `wall` for `frames` frames on both paths, keeping frames `keep`.
std::vector<std::string> run_args(const char* wall, int frames, const char* keep) {
  const fs::path file = fs::path(L2_SOURCE_DIR) / "examples/walls" / wall;
  return {"--wall",    file.string(), "--scene", "mesh", "--frames",  std::to_string(frames),
          "--refresh", "0",           "--path",  "both", "--compare", "--keep",
          keep};
}

std::vector<std::string> active_args() {
  return run_args("stereo-active-2x1.toml", 6, "4,5");
}

// Both paths' pictures of frames `frames` are the one-machine run's, byte for byte.
void expect_same_pictures(const WallRun& mpi, const WallRun& one,
                          std::initializer_list<int> frames) {
  for (const int k : frames) {
    for (int d = 0; d < 2; ++d) {
      for (const char* path : {"", "-vizserver"}) {
        const std::string name = fmt::format("frame-{}/display-{}{}.png", k, d, path);
        EXPECT_EQ(slurp(mpi.out() / name), slurp(one.out() / name)) << name;
        EXPECT_FALSE(slurp(one.out() / name).empty()) << name;
      }
    }
  }
}

TEST(MpiStereo, AnActiveWallShowsTheOneMachineRunsEyeFrames) {
  const MpirunBase base;
  std::vector<std::string> args = active_args();
  args.push_back("--mpi");
  // The coordinator, 2 pipeserver ranks, 1 board column.
  WallRun mpi("mpi-stereo-active", args, {}, false, mpirun(base, 4));
  ASSERT_TRUE(wait_mpirun(mpi, base, 180s).ok()) << mpi.output();
  const auto summary = active_stereo_summary(mpi.output());
  ASSERT_TRUE(summary) << mpi.output();
  EXPECT_EQ(summary->shown - summary->repeated, 3) << mpi.output();
  WallRun one("mpi-stereo-active-one", active_args());
  ASSERT_TRUE(one.wait(120s).ok()) << one.output();
  expect_same_pictures(mpi, one, {4, 5});
}

// A packed wall (side-by-side: each display both eyes, one in each half) over MPI: the ranks
// render and route a mono wall's frames, so both paths' displays equal the one-machine run's
// byte for byte, and the coordinator counts both eyes of every frame in the halves.
std::vector<std::string> packed_args() {
  return run_args("stereo-side-by-side-2x1.toml", 3, "2");
}

TEST(MpiStereo, APackedWallShowsTheOneMachineRunsHalves) {
  const MpirunBase base;
  std::vector<std::string> args = packed_args();
  args.push_back("--mpi");
  // The coordinator, 2 pipeserver ranks, 1 board column.
  WallRun mpi("mpi-stereo-packed", args, {}, false, mpirun(base, 4));
  ASSERT_TRUE(wait_mpirun(mpi, base, 180s).ok()) << mpi.output();
  EXPECT_NE(mpi.output().find("packed stereo (side-by-side): each of 2 display(s) showed both "
                              "eyes of each of its frames in its two halves in the same refresh"),
            std::string::npos)
      << mpi.output();
  WallRun one("mpi-stereo-packed-one", packed_args());
  ASSERT_TRUE(one.wait(120s).ok()) << one.output();
  expect_same_pictures(mpi, one, {2});
}

}  // namespace
}  // namespace l2
