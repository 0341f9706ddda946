// show_wall as a user runs it: a child process on a private Xvfb, its exit code, its error text
// and the screenshots it writes of what the screen showed.
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "base/child_process.hpp"
#include "displays/wall_view.hpp"
#include "displays/wall_window.hpp"
#include "image/png_io.hpp"
#include "screen_fixture.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// show_wall run to its end, its stdout and stderr captured.
Finished run_show_wall(std::vector<std::string> args) {
  args.insert(args.begin(), SHOW_WALL_EXE);
  return run(std::move(args), std::chrono::minutes(1));
}

class ShowWall : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    work_ = fs::temp_directory_path() / fmt::format("l2-show-wall-{}-{}", getpid(), info->name());
    fs::remove_all(work_);
    fs::create_directories(work_ / "displays");
  }
  void TearDown() override { fs::remove_all(work_); }
  fs::path work_;
};

TEST_F(ShowWall, HelpNamesEveryOption) {
  const Finished run = run_show_wall({"--help"});
  EXPECT_EQ(run.status.shell_code(), 0);
  for (const char* option : {"--displays-from", "--wall", "--show", "--frames", "--screenshot",
                             "--refresh", "--no-vsync", "monitors"}) {
    EXPECT_THAT(run.out, HasSubstr(option));
  }
}

TEST_F(ShowWall, EmptyFolderIsAClearError) {
  const Finished run = run_show_wall({"--displays-from", (work_ / "displays").string()});
  EXPECT_EQ(run.status.shell_code(), 1);
  EXPECT_THAT(run.err, HasSubstr("displays: no display-0.png to show"));
}

// The acceptance test: the default wall in the wall window for 5 frames; what the
// window shows, read back, equals the display images written for it, pixel for pixel.
TEST_F(ShowWall, DefaultWallWindowShowsTheWrittenDisplayImagesExactly) {
  const Wall wall = default_wall();
  std::vector<RgbImage> written;
  for (const Display& d : wall.displays) {
    RgbImage image(d.width, d.height);
    for (int y = 0; y < d.height; ++y) {
      for (int x = 0; x < d.width; ++x) image.set(x, y, test_pattern(d.id, x, y));
    }
    write_png(work_ / "displays" / fmt::format("display-{}.png", d.id), image);
    written.push_back(std::move(image));
  }
  std::ofstream(work_ / "default.toml") << default_wall_toml();
  const Rect extent = wall_extent(wall);
  L2_START_XVFB(xvfb, extent.w + 16,
                extent.h + WallWindow::kOverlayHeight + WallWindow::kDecorationAllowance + 16);
  const Finished run =
      run_show_wall({"--displays-from", (work_ / "displays").string(), "--wall",
                     (work_ / "default.toml").string(), "--frames", "5", "--screenshot",
                     (work_ / "shots").string(), "--no-vsync", "--refresh", "200"});
  ASSERT_EQ(run.status.shell_code(), 0) << run.err;
  for (const Display& d : wall.displays) {
    const RgbImage shown = read_png(work_ / "shots" / fmt::format("display-{}.png", d.id));
    EXPECT_TRUE(shown == written[d.id]) << "display " << d.id;
  }
}

TEST_F(ShowWall, DisplaysInARowAreShownExactly) {
  std::vector<RgbImage> written;
  for (int d = 0; d < 3; ++d) {
    written.push_back(testing::distinct_picture(d, 160 + 8 * d, 120));
    write_png(work_ / "displays" / fmt::format("display-{}.png", d), written.back());
  }
  L2_START_XVFB(xvfb, 1024, 768);
  const Finished run =
      run_show_wall({"--displays-from", (work_ / "displays").string(), "--frames", "5",
                     "--screenshot", (work_ / "shots").string(), "--no-vsync"});
  ASSERT_EQ(run.status.shell_code(), 0) << run.err;
  for (int d = 0; d < 3; ++d) {
    EXPECT_TRUE(read_png(work_ / "shots" / fmt::format("display-{}.png", d)) == written[d]);
  }
  const RgbImage window = read_png(work_ / "shots" / "window-0.png");
  EXPECT_EQ(window.width(), 160 + 168 + 176 + 2 * 16);  // mullions of 16 between the three
}

TEST_F(ShowWall, MonitorsModeWithFewerMonitorsThanDisplaysFailsListingThem) {
  for (int d = 0; d < 2; ++d) {
    write_png(work_ / "displays" / fmt::format("display-{}.png", d), RgbImage(64, 48));
  }
  L2_START_XVFB(xvfb, 800, 600);
  const Finished run = run_show_wall(
      {"--displays-from", (work_ / "displays").string(), "--show", "monitors", "--frames", "1"});
  EXPECT_EQ(run.status.shell_code(), 1);
  EXPECT_THAT(run.err, HasSubstr("--show monitors needs one monitor per display: 2 displays, "
                                 "but GLFW sees 1 monitor: [0] \""));
  EXPECT_THAT(run.err, HasSubstr("800x600 at (0,0)"));
}

}  // namespace
}  // namespace l2
