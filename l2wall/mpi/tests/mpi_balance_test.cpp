// `mpirun ... l2wall run --mpi --balance strips`: the pipeserver ranks send their times and
// take their layouts over MPI (MpiControlChannel), every host switching to frame k+1's layout
// together, and the displays of the last frame equal those of a static one-machine run byte for
// byte, each host's frame stamp aside (balanced_run.hpp). Real mpirun over the TCP transport.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "balanced_run.hpp"
#include "mpirun_run.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kFrames = 10;

// Patience for a loaded machine (six ranks on few cores).
const std::vector<std::string> kCommon{
    "--scene", "strips",          "--frames", std::to_string(kFrames), "--refresh", "0", "--keep",
    "9",       "--ready-timeout", "5000",     "--stall-timeout",       "60000"};

TEST(MpiBalance, StripsRetileOverMpiWithTheDisplaysOfAStaticRun) {
  std::vector<std::string> balanced_args = kCommon;
  balanced_args.insert(balanced_args.end(), {"--mpi", "--balance", "strips"});
  WallRun fixed("mpi-balance-static", kCommon);
  ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
  const MpirunBase base;
  WallRun balanced("mpi-balance-strips", balanced_args, {}, false, mpirun(base));
  ASSERT_TRUE(wait_mpirun(balanced, base, 180s).ok()) << balanced.output();
  const std::string output = balanced.output();

  // The summary names the mode and does not pretend to have counted strips.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m, std::regex("balance strips: (\\d+) layouts \\(from")))
      << output;
  const int layouts_counted = std::stoi(m[1].str());
  EXPECT_NE(output.find("strips routed per layout not counted"), std::string::npos) << output;
  // The ranks' batch footprints crossed MPI with their times (the strips scene's 98 batches).
  EXPECT_NE(output.find("balance: tiles priced by their pixels and the batches they touch (98 "
                        "batches a frame at most)"),
            std::string::npos)
      << output;
  // Every group swap was checked against the layouts, and none mixed two.
  ASSERT_TRUE(std::regex_search(
      output, m, std::regex("balance: (\\d+) of (\\d+) group swaps showed frames of two layouts")))
      << output;
  EXPECT_EQ(m[1].str(), "0");
  EXPECT_GE(std::stoi(m[2].str()), kFrames);
  EXPECT_NE(output.find("swap lock: every display"), std::string::npos) << output;

  const std::vector<TileLayout> layouts = layouts_of(balanced, default_wall());
  ASSERT_EQ(layouts.size(), static_cast<std::size_t>(kFrames));
  std::set<std::vector<Spot>> distinct;
  for (const TileLayout& l : layouts) distinct.insert(first_tiles_on(l, 0));
  EXPECT_GE(distinct.size(), 3u);
  EXPECT_GE(layouts_counted, static_cast<int>(distinct.size()));

  expect_displays_equal_stamps_aside(fixed, plan_layout(default_wall()), balanced, layouts, {9});
}

// Two board columns, both paths compared: each pipeserver's frames go to both columns (a layout
// may move its tiles onto the other's displays), and the columns composite its tiles too.
TEST(MpiBalance, TwoColumnsOnBothPathsRetileOverMpi) {
  const std::string wall_file = L2_SOURCE_DIR "/l2wall/mpi/tests/two-columns-3x3.toml";
  const std::vector<std::string> common{"--wall",   wall_file, "--scene",         "strips",
                                        "--frames", "6",       "--refresh",       "0",
                                        "--keep",   "5",       "--ready-timeout", "5000"};
  std::vector<std::string> balanced_args = common;
  balanced_args.insert(balanced_args.end(),
                       {"--mpi", "--balance", "strips", "--path", "both", "--compare"});
  WallRun fixed("mpi-balance-2col-static", common);
  ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
  // 2 pipeservers, 2 board columns, the coordinator.
  const MpirunBase base;
  WallRun balanced("mpi-balance-2col-strips", balanced_args, {}, false, mpirun(base, 5));
  ASSERT_TRUE(wait_mpirun(balanced, base, 180s).ok()) << balanced.output();
  const std::string output = balanced.output();
  EXPECT_NE(output.find("over 2 board column rank(s)"), std::string::npos) << output;
  EXPECT_TRUE(std::regex_search(
      output, std::regex("compare: [1-9][0-9]* display pictures identical byte for byte")))
      << output;
  EXPECT_NE(output.find("balance: 0 of "), std::string::npos) << output;
  const Wall wall = load_wall(wall_file);
  const std::vector<TileLayout> layouts = layouts_of(balanced, wall);
  ASSERT_EQ(layouts.size(), 6u);
  // The run did re-tile: LAYOUT lines that differ past their frame number.
  std::set<std::string> distinct;
  std::istringstream lines(slurp(balanced.out() / "layouts.txt"));
  for (std::string line; std::getline(lines, line);)
    distinct.insert(line.substr(line.find(' ', std::string("LAYOUT ").size())));
  EXPECT_GE(distinct.size(), 3u);
  expect_displays_equal_stamps_aside(fixed, plan_layout(wall), balanced, layouts, {5});
}

}  // namespace
}  // namespace l2
