// The report's swap time of frames around a pause: the pause held the frame back, it is not swap
// time (a newcomer saw the largest swap time be the length of a pause from the control page).
#include "l2wall/run_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

// Each pipeserver's log opens with the renderer it decided on (--renderer): said once when all
// decided alike, a line each when not, and "not said" for one that stopped before deciding.
TEST(RunReport, SaysWhatThePipeserversRenderWith) {
  const auto dir = std::filesystem::temp_directory_path() / "l2-run-report-renderer-test";
  std::filesystem::create_directories(dir);
  RunOptions o;
  o.out = dir.string();
  const auto log = [&](int i, const std::string& text) {
    const auto path = dir / ("pipeserver-" + std::to_string(i) + ".log");
    std::ofstream(path) << text;
    return path.string();
  };
  const std::string osmesa =
      "osmesa (llvmpipe (LLVM 15.0.6, 256 bits); auto: no GPU: EGL finds only Mesa's software "
      "device (llvmpipe))";
  const std::string egl =
      "egl (a GPU's renderer, EGL device: GPU /dev/dri/renderD128; auto: EGL finds a GPU)";
  std::vector<FrameRecord> records(1);
  const auto summary = [&](const std::vector<std::string>& logs) {
    return run_report(o, default_wall(), logs, records, RunTotals{}, "", "").summary;
  };
  const std::string frame = "frame 0 render_ms 1.0 wait_ms 0.0 retries 0\n";
  const std::string alike =
      summary({log(0, "renderer " + osmesa + "\n" + frame), log(1, "renderer " + osmesa + "\n")});
  EXPECT_NE(alike.find("\nrenderer: " + osmesa + ", on every pipeserver\n"), std::string::npos)
      << alike;
  const std::string mixed = summary(
      {log(0, "renderer " + osmesa + "\n"), log(1, "renderer " + egl + "\n"), log(2, frame)});
  EXPECT_NE(mixed.find("\nrenderer pipeserver 0: " + osmesa + "\nrenderer pipeserver 1: " + egl +
                       "\nrenderer pipeserver 2: not said (it stopped before rendering)\n"),
            std::string::npos)
      << mixed;
  const std::string none = summary({log(0, ""), log(1, "")});
  EXPECT_NE(none.find("\nrenderer: not said (no pipeserver got as far as rendering)\n"),
            std::string::npos)
      << none;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace l2
