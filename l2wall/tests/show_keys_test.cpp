// `l2wall run --show` keys typed through XTEST, as a keyboard would, into the wall window of a
// live run on a private Xvfb: space holds the pipeservers, s saves screenshots, q and Esc end the
// run.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "displays/x_client.hpp"
#include "image/png_io.hpp"
#include "show_run.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

TEST(Show, SpacePausesTheHostsSSavesScreenshotsQEndsTheRunCleanly) {
  L2_START_XVFB(xvfb, 800, 600);
  const fs::path wall =
      write_small_wall(fs::temp_directory_path() / fmt::format("l2wall-keys-{}", getpid()));
  const int planned = 300;
  // READY timeout 300 ms: the pause below outlasts a few of them, SYNC? asked meanwhile.
  WallRun run("show-keys",
              {"--wall", wall.string(), "--show", "window", "--frames", std::to_string(planned),
               "--keep", "every", "--refresh", "60", "--ready-timeout", "300"});
  testing::XClient x(xvfb.display());
  const unsigned long window = x.wait_for_window(kSmallTitle, 20s);
  ASSERT_NE(window, 0u) << run.output();
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();

  x.type(window, "space");
  const int paused = wait_for_output(run, "paused at frame (\\d+)", 5s);
  ASSERT_GE(paused, 0) << run.output();
  // A pipeserver may still publish the frame it was rendering; then all wait for a READY that does
  // not come, for longer than a few READY timeouts, asking with SYNC? meanwhile.
  std::this_thread::sleep_for(300ms);
  const std::vector<int> held = pipeserver_lines(run, 2);
  std::this_thread::sleep_for(1000ms);
  EXPECT_EQ(pipeserver_lines(run, 2), held) << "the pipeservers went on while paused";
  EXPECT_FALSE(fs::exists(run.out() / fmt::format("frame-{}", paused + 1)))
      << "a frame reached the displays while paused";

  // s: every display as the screen shows it, equal to what the run wrote for that frame.
  x.type(window, "s");
  const fs::path shots = run.out() / "screenshots";
  ASSERT_TRUE(wait_for_file(shots / fmt::format("frame-{}-window-0.png", paused), 5s))
      << run.output();
  for (int d = 0; d < 2; ++d) {
    const RgbImage shot = read_png(shots / fmt::format("frame-{}-display-{}.png", paused, d));
    EXPECT_TRUE(shot == display_png(run.out(), paused, d)) << "display " << d;
  }
  // And independently of the run's read-back: this test's own look at the window.
  EXPECT_TRUE(x.read(window, 0, 0, 320, 240) == display_png(run.out(), paused, 0));
  EXPECT_TRUE(x.read(window, 336, 0, 320, 240) == display_png(run.out(), paused, 1));

  x.type(window, "space");
  ASSERT_GE(wait_for_output(run, "resumed at frame (\\d+)", 5s), 0) << run.output();
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (pipeserver_lines(run, 2)[0] < held[0] + 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  EXPECT_GE(pipeserver_lines(run, 2)[0], held[0] + 3)
      << "the pipeservers did not go on after resuming";

  x.type(window, "q");
  const ExitStatus status = run.wait(15s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  const int last = wait_for_output(run, "quit by the user after frame (\\d+) of 300", 0s);
  ASSERT_GT(last, paused) << output;
  EXPECT_NE(output.find("paused 1 time"), std::string::npos) << output;
  EXPECT_NE(output.find("1 screenshot in"), std::string::npos) << output;
  EXPECT_NE(output.find(fmt::format("{} frames on 2 displays", last + 1)), std::string::npos)
      << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_NE(summary.find("quit by the user"), std::string::npos) << summary;
  // The pipeservers were stopped while rendering frames past the quit: no totals, and said so.
  EXPECT_NE(summary.find("back-channel pipeserver 0: no totals (stopped before its last frame)"),
            std::string::npos)
      << summary;
  EXPECT_EQ(read_csv(run.out() / "report.csv").size(), static_cast<std::size_t>(last + 2));
  expect_clean(run);
  fs::remove_all(wall.parent_path());
}

TEST(Show, EscapeEndsTheRunLikeQ) {
  L2_START_XVFB(xvfb, 800, 600);
  const fs::path wall =
      write_small_wall(fs::temp_directory_path() / fmt::format("l2wall-esc-{}", getpid()));
  WallRun run("show-esc",
              {"--wall", wall.string(), "--show", "window", "--frames", "300", "--keep", "last"});
  testing::XClient x(xvfb.display());
  const unsigned long window = x.wait_for_window(kSmallTitle, 20s);
  ASSERT_NE(window, 0u) << run.output();
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();
  x.type(window, "Escape");
  const ExitStatus status = run.wait(15s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  const int last = wait_for_output(run, "quit by the user after frame (\\d+) of 300", 0s);
  ASSERT_GE(last, 0) << output;
  // --keep last: the frame the run ended on.
  EXPECT_TRUE(fs::exists(run.out() / fmt::format("frame-{}", last) / "display-0.png"));
  expect_clean(run);
  fs::remove_all(wall.parent_path());
}
}  // namespace
}  // namespace l2
