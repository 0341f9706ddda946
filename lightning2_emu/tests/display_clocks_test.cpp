// Frame lock in virtual time: the counts below are derived by hand from the retrace times
// n / (1 + ppm·1e-6), in house refreshes.
#include "lightning2_emu/display_clocks.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace l2 {
namespace {

SwapGroup clock_group(int id, std::vector<int> displays) {
  SwapGroup g;
  g.id = id;
  g.displays = std::move(displays);
  return g;
}

// Runs `refreshes` house refreshes in which the locked frame of every display is the refresh
// number (a new frame every refresh); returns the refreshes a group of all displays mismatched.
std::vector<std::uint64_t> refreshes_mismatched(DisplayClocks& clocks, int refreshes) {
  std::vector<std::uint64_t> at;
  std::uint64_t before = 0;
  for (int s = 0; s < refreshes; ++s) {
    const std::vector<int> locked(clocks.ppm().size(), s);
    clocks.refresh(locked);
    if (clocks.mismatched()[0] != before) at.push_back(static_cast<std::uint64_t>(s));
    before = clocks.mismatched()[0];
  }
  return at;
}

// A display at -1000 ppm retraces every 1000/999 house periods: retrace n at n·1.001001...
// Between pulses 0 and 1 it has none (its first is at 1.001), nor between 1000 and 1001 (999.999
// then 1001.001), nor between 2000 and 2001: it shows the frame before at refreshes 1, 1001, 2001.
TEST(DisplayClocks, SlowerDisplaySlipsOnceEveryThousandRefreshesAtMinus1000Ppm) {
  DisplayClocks clocks({0, -1000}, {clock_group(0, {0, 1})}, false);
  EXPECT_EQ(refreshes_mismatched(clocks, 3000), (std::vector<std::uint64_t>{1, 1001, 2001}));
  EXPECT_EQ(clocks.mismatched()[0], 3u);
  // Refresh 2999: the house display's 2999th retrace; the slow one's last is floor(2999·0.999).
  EXPECT_EQ(clocks.counters()[0], 2999);
  EXPECT_EQ(clocks.counters()[1], 2996);
  EXPECT_EQ(clocks.shown()[0], 2999);
  EXPECT_EQ(clocks.shown()[1], 2999);
}

TEST(DisplayClocks, ShowsTheFrameBeforeInTheRefreshItSlips) {
  DisplayClocks clocks({0, -1000}, {clock_group(0, {0, 1})}, false);
  clocks.refresh(std::vector<int>{7, 7});
  clocks.refresh(std::vector<int>{8, 8});  // refresh 1: no retrace of display 1 since 0
  EXPECT_EQ(clocks.shown(), (std::vector<int>{8, 7}));
  EXPECT_EQ(clocks.counters(), (std::vector<std::int64_t>{1, 0}));
  clocks.refresh(std::vector<int>{8, 8});  // its retrace at 1.001 took frame 8
  EXPECT_EQ(clocks.shown(), (std::vector<int>{8, 8}));
  EXPECT_EQ(clocks.mismatched()[0], 1u);
}

// A frame that stays up through the slip shows no mismatch: only a change can be caught late.
TEST(DisplayClocks, NoNewFrameNoMismatch) {
  DisplayClocks clocks({0, -1000}, {clock_group(0, {0, 1})}, false);
  for (int s = 0; s < 3000; ++s) clocks.refresh(std::vector<int>{s / 2000, s / 2000});
  // Frame 1 first shows at refresh 2000, where display 1 retraces too (1998 / 0.999); its slip
  // at 2001 shows frame 1 still, as the house display does.
  EXPECT_EQ(clocks.mismatched()[0], 0u);
}

// +1000 ppm retraces in every house period (period 0.999) and gains one every 1000 refreshes:
// its counter runs ahead, but at every pulse it has taken the newest frame.
TEST(DisplayClocks, FasterDisplayGainsRetracesButIsNeverBehind) {
  DisplayClocks clocks({0, 1000}, {clock_group(0, {0, 1})}, false);
  EXPECT_TRUE(refreshes_mismatched(clocks, 3000).empty());
  EXPECT_EQ(clocks.counters()[1], 3001);  // floor(2999·1.001)
}

// A 10 % slow display, as a short live run uses: retraces at n / 0.9, none between pulses 0-1,
// 10-11, 20-21, ...: at refreshes 1, 11, 21, 31 in 40 refreshes.
TEST(DisplayClocks, LargeDriftShowsInAShortRun) {
  DisplayClocks clocks({0, 0, -100000}, {clock_group(3, {0, 1, 2})}, false);
  EXPECT_EQ(refreshes_mismatched(clocks, 40), (std::vector<std::uint64_t>{1, 11, 21, 31}));
  EXPECT_EQ(clocks.counters()[2], 35);  // floor(39·0.9)
}

TEST(DisplayClocks, HouseSyncLocksEveryDisplay) {
  DisplayClocks clocks({0, -100000, 100000, -500000}, {clock_group(0, {0, 1, 2, 3})}, true);
  EXPECT_TRUE(refreshes_mismatched(clocks, 3000).empty());
  EXPECT_EQ(clocks.counters(), (std::vector<std::int64_t>{2999, 2999, 2999, 2999}));
}

// Groups are counted apart: a slow display only breaks its own group.
TEST(DisplayClocks, CountsPerGroup) {
  DisplayClocks clocks({0, -100000, 0, 0}, {clock_group(0, {0, 1}), clock_group(1, {2, 3})}, false);
  for (int s = 0; s < 40; ++s) clocks.refresh(std::vector<int>(4, s));
  EXPECT_EQ(clocks.mismatched(), (std::vector<std::uint64_t>{4, 0}));
}

// Displays without a frame yet (-1) are not compared, as in the swap-lock check.
TEST(DisplayClocks, DisplaysWithoutAFrameAreNotCompared) {
  DisplayClocks clocks({0, -1000}, {clock_group(0, {0, 1})}, false);
  clocks.refresh(std::vector<int>{-1, -1});
  clocks.refresh(std::vector<int>{0, 0});  // display 1 still shows -1 (none)
  EXPECT_EQ(clocks.shown(), (std::vector<int>{0, -1}));
  EXPECT_EQ(clocks.mismatched()[0], 0u);
}

// Half the rate, the slowest allowed: every other pulse it shows the frame before.
TEST(DisplayClocks, HalfRateShowsEveryOtherFrameLate) {
  DisplayClocks clocks({0, -500000}, {clock_group(0, {0, 1})}, false);
  EXPECT_EQ(refreshes_mismatched(clocks, 6), (std::vector<std::uint64_t>{1, 3, 5}));
}

TEST(DisplayClocks, RefusesClocksBeyondTheRangeAndUnknownDisplays) {
  EXPECT_THROW(DisplayClocks({500001}, {}, false), std::invalid_argument);
  EXPECT_THROW(DisplayClocks({-500001}, {}, false), std::invalid_argument);
  EXPECT_THROW(DisplayClocks({0}, {clock_group(0, {0, 1})}, false), std::invalid_argument);
}

}  // namespace
}  // namespace l2
