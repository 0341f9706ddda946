// The live run's record of frame lock: what the columns' displays hold in lock in, frame-lock.csv
// and the summary line out.
#include "l2wall/frame_lock_record.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace l2 {
namespace {

Wall clocked_pair(int slow_ppm, bool house_sync) {
  Wall wall;
  wall.displays.resize(2);
  wall.displays[1].id = 1;
  wall.displays[1].clock_ppm = slow_ppm;
  wall.frame_lock.modelled = true;
  wall.frame_lock.house_sync = house_sync;
  return wall;
}

std::vector<SwapGroup> pair_group() {
  SwapGroup g;
  g.id = 5;
  g.displays = {0, 1};
  return {g};
}

// Display 1 at half the rate retraces at house refreshes 0, 2, 4: at 1 and 3 it still shows the
// frame of the refresh before.
TEST(FrameLockRecord, CsvAndSummaryOfAHalfRateDisplay) {
  FrameLockRecord record(clocked_pair(-500000, false), pair_group());
  for (int frame : {-1, 0, 0, 1}) {
    record.refresh(std::vector<DisplayShown>{{0, frame, 0}, {1, frame, 0}});
  }
  EXPECT_EQ(record.csv(),
            "refresh,counter_0,frame_0,counter_1,frame_1,mismatched_groups\n"
            "0,0,-1,0,-1,\n"
            "1,1,0,0,-1,\n"
            "2,2,0,1,0,\n"
            "3,3,1,1,0,5\n");
  EXPECT_EQ(record.summary_lines(),
            "frame lock: display clocks run free (clock_ppm): mismatched refreshes (a swap "
            "group's displays showing different frames) of 4: group 5: 1; each display's frame "
            "counter and frame per refresh in frame-lock.csv\n");
  EXPECT_EQ(record.shown(1), 0);
  EXPECT_EQ(record.shown_lines(),
            "refresh 3\n"
            "display 0: frame 1, counter 3\n"
            "display 1: frame 0, counter 1\n");
}

TEST(FrameLockRecord, HouseSyncAndDisplaysNoColumnAnswered) {
  FrameLockRecord record(clocked_pair(-500000, true), pair_group());
  record.refresh(std::vector<DisplayShown>{{0, 3, 0}});  // display 1's column did not answer
  record.refresh(std::vector<DisplayShown>{{0, 4, 0}, {1, 4, 1}, {7, 4, 1}});  // 7: no such
  EXPECT_EQ(record.csv(),
            "refresh,counter_0,frame_0,counter_1,frame_1,mismatched_groups\n"
            "0,0,3,0,-1,\n"
            "1,1,4,1,4,\n");
  EXPECT_NE(record.summary_lines().find("house sync locks every display's clock: mismatched "
                                        "refreshes (a swap group's displays showing different "
                                        "frames) of 2: group 5: 0;"),
            std::string::npos)
      << record.summary_lines();
}

// A long run keeps the first rows its cells allow, and says so: 6 cells a row of two displays.
TEST(FrameLockRecord, CsvRowsAreBounded) {
  FrameLockRecord record(clocked_pair(0, false), pair_group(), 20);
  for (int i = 0; i < 10; ++i) record.refresh({});
  EXPECT_EQ(record.csv(),
            "refresh,counter_0,frame_0,counter_1,frame_1,mismatched_groups\n"
            "0,0,-1,0,-1,\n"
            "1,1,-1,1,-1,\n"
            "2,2,-1,2,-1,\n");
  EXPECT_NE(record.summary_lines().find("of 10: group 5: 0; frame-lock.csv holds the first 3 "
                                        "refreshes\n"),
            std::string::npos)
      << record.summary_lines();
}

}  // namespace
}  // namespace l2
