// The report's swap time of frames around a pause: the pause held the frame back, it is not swap
// time (a newcomer saw the largest swap time be the length of a pause from the control page).
#include "l2wall/run_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

using std::chrono::milliseconds;

TEST(RunReport, SwapTimeLeavesOutAPauseBeforeTheSwap) {
  RunOptions o;
  o.out = (std::filesystem::temp_directory_path() / "l2-run-report-test").string();
  RunTotals totals;
  totals.pace = "3 refreshes at 60 Hz";
  totals.start = RunClock::time_point{} + milliseconds(1000);
  std::vector<FrameRecord> records(3);
  for (std::size_t k = 0; k < records.size(); ++k) {
    records[k].in_refresh = k;
    records[k].swap_refresh = k + 1;
    records[k].in_time = totals.start + milliseconds(100 * k);
    records[k].swap_time = records[k].in_time + milliseconds(20);
    records[k].shown = true;
  }
  // Frame 1 waited 500 ms of pause between its input and its swap.
  records[1].swap_time += milliseconds(500);
  records[1].paused_ms = records[2].paused_ms = 500;
  records[2].in_time += milliseconds(500);
  records[2].swap_time += milliseconds(500);
  const RunReportTexts report = run_report(o, default_wall(), {}, records, totals, "", "");
  EXPECT_NE(report.csv.find("\n0,0,1,1,0.000,20.000\n1,1,2,1,0.000,20.000\n2,2,3,1,0.000,20.000\n"),
            std::string::npos)
      << report.csv;
  EXPECT_TRUE(
      std::regex_search(report.summary, std::regex("swap time[^\n]*: 20.0 / 20.0 / 20.0 ms")))
      << report.summary;
}

}  // namespace
}  // namespace l2
