// The summary's spread of times and the cause it names, from times chosen by hand.
#include "run_stats.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(RunStats, NearestRankPercentiles) {
  // 1..20: the median is the 10th value, the 95th percentile the 19th.
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);
  const auto s = spread_of(v);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->p50, 10);
  EXPECT_EQ(s->p95, 19);
  EXPECT_EQ(s->max, 20);
  const auto one = spread_of({7.5});
  ASSERT_TRUE(one);
  EXPECT_EQ(one->p50, 7.5);
  EXPECT_EQ(one->p95, 7.5);
  EXPECT_FALSE(spread_of({}));
}

TEST(RunStats, NamesTheHostWhoseMedianRenderTimeIsLongest) {
  RunTimes t;
  t.render = {{5, 6, 7}, {21, 22, 40}, {3, 3, 3}};
  t.route = {1, 2, 9};
  t.swap = {17, 18, 30};
  t.refresh_hz = 60;
  EXPECT_EQ(spread_lines(t),
            "render time of pipeserver 0 (median / 95th percentile / max): 6.0 / 7.0 / 7.0 ms\n"
            "render time of pipeserver 1 (median / 95th percentile / max): 22.0 / 40.0 / 40.0 "
            "ms\n"
            "render time of pipeserver 2 (median / 95th percentile / max): 3.0 / 3.0 / 3.0 ms\n"
            "route time of the emulator (median / 95th percentile / max): 2.0 / 9.0 / 9.0 ms\n"
            "swap time, input taken in to displays swapped (median / 95th percentile / max): "
            "18.0 / 30.0 / 30.0 ms\n"
            "limited by pipeserver 1's render time: median 22.0 ms\n");
}

// A pipeserver lost mid-run rendered a frame or two, slowly (a first frame): listed, not the
// limit.
TEST(RunStats, ALostPipeserverIsListedButNotTheLimit) {
  RunTimes t;
  t.render = {{5, 6, 7}, {300}, {3, 3, 3}};
  t.lost = {false, true, false};
  t.refresh_hz = 0;
  EXPECT_EQ(spread_lines(t),
            "render time of pipeserver 0 (median / 95th percentile / max): 6.0 / 7.0 / 7.0 ms\n"
            "render time of pipeserver 1 (median / 95th percentile / max): 300.0 / 300.0 / 300.0 "
            "ms (lost mid-run)\n"
            "render time of pipeserver 2 (median / 95th percentile / max): 3.0 / 3.0 / 3.0 ms\n"
            "limited by pipeserver 0's render time: median 6.0 ms\n");
}

TEST(RunStats, NamesTheRefreshRateWhenEveryoneKeepsUp) {
  RunTimes t;
  t.render = {{5, 6}};
  t.route = {1, 1};
  t.refresh_hz = 60;
  const std::string lines = spread_lines(t);
  EXPECT_NE(lines.find("\nlimited by the refresh rate: 60 Hz, 16.7 ms a refresh\n"),
            std::string::npos)
      << lines;
}

TEST(RunStats, NamesTheEmulatorWhenRoutingIsSlowest) {
  RunTimes t;
  t.render = {{5, 6}, {4, 4}};
  t.route = {12, 14};
  const std::string lines = spread_lines(t);
  EXPECT_NE(lines.find("\nlimited by the emulator's route time: median 12.0 ms\n"),
            std::string::npos)
      << lines;
}

}  // namespace
}  // namespace l2
