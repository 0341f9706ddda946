// `l2wall run` at a refresh rate (spec §6.4): READY goes out in the refresh the frame completes,
// so pipeservers that render faster than the refresh rate put a new frame on the displays at every
// refresh, each with one frame of latency. Judged from the run's own counts (report.csv and
// summary.txt), not from wall-clock rates. Not in the sanitizer runs: there the pipeservers
// render too slowly to keep up with any refresh rate.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

class AtTheRefreshRate : public ::testing::TestWithParam<int> {};

TEST_P(AtTheRefreshRate, ANewFrameReachesTheDisplaysAtNearlyEveryRefresh) {
  const int hz = GetParam();
  const int frames = 40;
  WallRun run(fmt::format("refresh-{}", hz),
              {"--frames", std::to_string(frames), "--refresh", std::to_string(hz)});
  const ExitStatus status = run.wait(60s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m,
                                std::regex(fmt::format("\\(([0-9]+) refreshes at {} Hz\\)", hz))))
      << output;
  const int refreshes = std::stoi(m[1]);

  const auto rows = read_csv(run.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(frames + 1));
  ASSERT_EQ(rows[0][1], "in_refresh");
  ASSERT_EQ(rows[0][2], "swap_refresh");
  std::vector<std::size_t> waits;  // the columns of the pipeservers' READY waits
  for (std::size_t c = 0; c < rows[0].size(); ++c) {
    if (rows[0][c].rfind("ready_wait_ms_", 0) == 0) waits.push_back(c);
  }
  ASSERT_EQ(waits.size(), 4u);
  std::string late;  // frames that came late although every pipeserver had it rendered before READY
  int late_count = 0;
  for (int k = 1; k <= frames; ++k) {
    const auto& row = rows[static_cast<std::size_t>(k)];
    EXPECT_EQ(row[3], "1") << "latency of frame " << k - 1;
    EXPECT_EQ(std::stoi(row[2]), std::stoi(row[1]) + 1) << "frame " << k - 1;
    if (k == 1) continue;
    const int gap = std::stoi(row[1]) - std::stoi(rows[static_cast<std::size_t>(k - 1)][1]);
    // A pipeserver that finished rendering after READY had come was the one that was late (the
    // machine is shared); one that waited for READY swapped its frame in at READY.
    bool every_pipeserver_waited = true;
    for (const std::size_t c : waits) every_pipeserver_waited &= std::stod(row[c]) >= 0.5;
    if (gap > 1 && every_pipeserver_waited) {
      ++late_count;
      late += fmt::format(" {} ({} refreshes)", k - 1, gap);
    }
  }
  // The last swap is the run's last refresh (refreshes count from 0).
  EXPECT_EQ(refreshes, std::stoi(rows[frames][2]) + 1) << output;
  // Waiting for READY until the swap, as before spec §6.4 changed, every frame took two
  // refreshes. Now a frame whose pipeservers all had it ready comes at the next refresh, but for a
  // pipeserver woken late now and then on a loaded machine: how often is the scheduler's, so the
  // bound is half the frames, which that regression (all of them late) still exceeds.
  EXPECT_LE(late_count, frames / 2) << "late frames:" << late << "\n" << output;
  expect_clean(run);
}

// report.csv's route_ms is the emulator time of the refreshes that took a frame in: a refresh
// that takes in the frame of all 12 pipeservers of the WireGL wall counts once, not once per
// pipeserver. At 90 Hz the run mostly waits for the next refresh, so routing is a small part of its
// time.
TEST(LiveRun, RouteTimeCountsEachRefreshOncePerFrame) {
  const int frames = 20;
  WallRun run("route-ms",
              {"--wall", std::string(L2_SOURCE_DIR) + "/walls/wiregl-1600x1200.toml", "--scene",
               "swap", "--frames", std::to_string(frames), "--refresh", "90"});
  const ExitStatus status = run.wait(60s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m, std::regex("pipeservers in ([0-9.]+) s: "))) << output;
  const double run_ms = std::stod(m[1]) * 1000.0;
  const auto rows = read_csv(run.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(frames + 1));
  ASSERT_EQ(rows[0][4], "route_ms");
  double route_ms = 0;
  for (int k = 1; k <= frames; ++k) route_ms += std::stod(rows[static_cast<std::size_t>(k)][4]);
  EXPECT_GT(route_ms, 0.0);
  EXPECT_LT(route_ms, 0.5 * run_ms) << output;
  expect_clean(run);
}

INSTANTIATE_TEST_SUITE_P(LiveRun, AtTheRefreshRate, ::testing::Values(60, 90),
                         [](const ::testing::TestParamInfo<int>& p) {
                           return fmt::format("Hz{}", p.param);
                         });

}  // namespace
}  // namespace l2
