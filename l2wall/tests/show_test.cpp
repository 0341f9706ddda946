// `l2wall run --show` end to end on a private Xvfb: real pipeserver processes, the wall window
// read back from the X server against the displays the run wrote, and the refusals.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "image/png_io.hpp"
#include "show_run.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

TEST(Show, WallWindowShowsTheWrittenDisplaysPixelForPixel) {
  L2_START_XVFB(xvfb, kScreenW, kScreenH);
  const int frames = 5;
  const fs::path readback = fs::temp_directory_path() / fmt::format("l2wall-readback-{}", getpid());
  fs::remove_all(readback);
  WallRun run("show-window", {"--show", "window", "--frames", std::to_string(frames), "--keep",
                              "every", "--refresh", "0", "--show-readback", readback.string()});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("show: window, 5 frames presented"), std::string::npos) << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  for (int k = 0; k < frames; ++k) {
    for (int d = 0; d < 4; ++d) {
      const RgbImage written = display_png(run.out(), k, d);
      ASSERT_EQ(written.width(), 640);
      EXPECT_TRUE(display_png(readback, k, d) == written) << "frame " << k << " display " << d;
    }
  }
  // The whole window: displays where the wall file puts them, mullions dark, overlay below.
  const RgbImage window = read_png(readback / "frame-4" / "window-0.png");
  ASSERT_EQ(window.width(), 1300);
  ASSERT_GT(window.height(), 980);
  const RgbImage d3 = display_png(run.out(), 4, 3);
  for (int y = 0; y < 480; y += 7) {
    EXPECT_EQ(window.at(650, y), kMullion) << y;
    EXPECT_EQ(window.at(660 + y % 640, 500 + y), d3.at(y % 640, y)) << y;
  }
  fs::remove_all(readback);
  expect_clean(run);
}

TEST(Show, MonitorsWithFewerMonitorsThanDisplaysIsRefusedListingThem) {
  L2_START_XVFB(xvfb, 800, 600);
  WallRun run("show-monitors", {"--show", "monitors", "--frames", "3"});
  const ExitStatus status = run.wait(20s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  // One line: what is wrong, and the monitors there are.
  EXPECT_EQ(output,
            "l2wall: walls/kd-2x2.toml (built in): --show monitors needs one monitor per display: "
            "4 displays, but GLFW sees 1 monitor: [0] \"screen\" 800x600 at (0,0)\n");
  // Refused before any pipeserver started.
  EXPECT_FALSE(fs::exists(run.out() / "pipeserver-0.log"));
  expect_clean(run);
}

// A wall whose one display names Xvfb's one monitor ("screen", its RandR output) goes
// fullscreen there, pixel for pixel.
TEST(Show, MonitorsShowsADisplayFullscreenOnTheMonitorItsWallFileNames) {
  L2_START_XVFB(xvfb, 800, 600);
  const ScratchDir dir("monitor");
  std::ofstream(dir / "one.toml") << R"(name = "one monitor"
[display_grid]
columns = 1
rows = 1
width = 640
height = 480
monitors = ["screen"]
[tiling]
kind = "grid"
tile_width = 320
tile_height = 240
[pipeservers]
count = 2
framebuffer_width = 800
framebuffer_height = 600
)";
  WallRun run("show-monitor",
              {"--wall", (dir / "one.toml").string(), "--show", "monitors", "--frames", "3",
               "--refresh", "0", "--keep", "every", "--show-readback", (dir / "screen").string()});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("show: monitors, 3 frames presented"), std::string::npos) << output;
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(display_png(dir / "screen", k, 0) == display_png(run.out(), k, 0)) << "frame " << k;
  }
  // Fullscreen: the window is the monitor, the display centred in black.
  const RgbImage window = read_png(dir / "screen" / "frame-2" / "window-0.png");
  EXPECT_EQ(window.width(), 800);
  EXPECT_EQ(window.height(), 600);
  EXPECT_EQ(window.at(0, 0), Rgb{});
  EXPECT_EQ(window.at(80 + 320, 60 + 240), display_png(run.out(), 2, 0).at(320, 240));
  expect_clean(run);
}

// The wall window on a wall of one landscape panel and one hung at 90 (300x200 native, 200x300 on
// the canvas, 10 pixels right of the first): the turned panel stands upright where the wall file
// puts it, and read back it is its frame again, byte for byte.
TEST(Show, WallWindowDrawsATurnedPanelAsItHangs) {
  L2_START_XVFB(xvfb, 800, 600);
  const ScratchDir dir("turned");
  std::ofstream(dir / "turned.toml") << R"(name = "turned"
[[display]]
width = 300
height = 200
x = 0
y = 0
[[display]]
width = 300
height = 200
x = 310
y = 0
rotation = 90
[tiling]
kind = "grid"
tile_width = 128
tile_height = 128
[pipeservers]
count = 2
framebuffer_width = 700
framebuffer_height = 500
)";
  WallRun run("show-turned",
              {"--wall", (dir / "turned.toml").string(), "--show", "window", "--frames", "2",
               "--refresh", "0", "--keep", "every", "--show-readback", (dir / "screen").string()});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  for (int d = 0; d < 2; ++d)
    EXPECT_TRUE(display_png(dir / "screen", 1, d) == display_png(run.out(), 1, d)) << d;
  // Window pixel (310 + u, v) shows canvas offset (u, v) of display 1: its panel pixel
  // (v, 199 - u) at 90 (docs/wall-file.md).
  const RgbImage window = read_png(dir / "screen" / "frame-1" / "window-0.png");
  const RgbImage turned = display_png(run.out(), 1, 1);
  for (const auto& [u, v] :
       {std::pair{0, 0}, std::pair{199, 0}, std::pair{37, 250}, std::pair{199, 299}})
    EXPECT_EQ(window.at(310 + u, v), turned.at(v, 199 - u)) << u << "," << v;
  EXPECT_EQ(window.at(305, 100), kMullion);
  expect_clean(run);
}

// A panel hung in portrait (rotation 90: 600x400 native, 400x600 on the canvas) on a landscape
// monitor stands upright in the middle of it; read back and turned into its raster again, it is
// the display's frame. A portrait panel taller than its monitor is shown scaled down, said once.
std::string portrait_wall(const fs::path& dir, int width, int height) {
  const fs::path file = dir / fmt::format("portrait-{}x{}.toml", width, height);
  std::ofstream(file) << fmt::format(R"(name = "one portrait panel"
[[display]]
width = {}
height = {}
x = 0
y = 0
rotation = 90
monitor = "screen"
[tiling]
kind = "grid"
tile_width = 200
tile_height = 200
[pipeservers]
count = 2
framebuffer_width = 1024
framebuffer_height = 1024
[mesh]
board_max_width = 1024
board_max_height = 1024
)",
                                     width, height);
  return file.string();
}

TEST(Show, MonitorsShowAPortraitPanelUpright) {
  L2_START_XVFB(xvfb, 800, 600);
  const ScratchDir dir("portrait");
  WallRun run("show-portrait",
              {"--wall", portrait_wall(dir.path(), 600, 400), "--show", "monitors", "--frames", "2",
               "--refresh", "0", "--keep", "every", "--show-readback", (dir / "screen").string()});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_EQ(output.find("--show: display 0"), std::string::npos) << output;  // it fits
  const RgbImage frame = display_png(run.out(), 1, 0);
  EXPECT_TRUE(display_png(dir / "screen", 1, 0) == frame);
  // Upright and centred: window pixel (200 + u, v) shows canvas offset (u, v), which at 90 is
  // panel pixel (v, 399 - u) (docs/wall-file.md: panel (x, y) shows (cw - 1 - y, x)).
  const RgbImage window = read_png(dir / "screen" / "frame-1" / "window-0.png");
  for (const auto& [u, v] :
       {std::pair{10, 20}, std::pair{399, 0}, std::pair{0, 599}, std::pair{250, 300}})
    EXPECT_EQ(window.at(200 + u, v), frame.at(v, 399 - u)) << u << "," << v;
  EXPECT_EQ(window.at(100, 300), Rgb{});  // beside it, black
  expect_clean(run);
}

TEST(Show, APanelLargerThanItsMonitorIsSaidOnce) {
  L2_START_XVFB(xvfb, 800, 600);
  const ScratchDir dir("tall");
  WallRun run("show-tall", {"--wall", portrait_wall(dir.path(), 1000, 700), "--show", "monitors",
                            "--frames", "2", "--refresh", "0"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  const std::string said =
      "--show: display 0 (700x1000 as it hangs) is shown at 60% on monitor screen (800x600): the "
      "monitor is smaller than the panel\n";
  ASSERT_NE(output.find(said), std::string::npos) << output;
  EXPECT_EQ(output.find(said), output.rfind(said)) << output;
  expect_clean(run);
}

TEST(Show, WithoutAScreenTheErrorIsOneLine) {
  const char* saved = std::getenv("DISPLAY");
  const std::string keep = saved ? saved : "";
  unsetenv("DISPLAY");
  WallRun run("show-noscreen", {"--show", "window", "--frames", "3"});
  const ExitStatus status = run.wait(20s);
  if (saved) setenv("DISPLAY", keep.c_str(), 1);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_EQ(output.rfind("l2wall: cannot open the screen: ", 0), 0u) << output;
  EXPECT_NE(output.find("DISPLAY=unset"), std::string::npos) << output;
  EXPECT_NE(output.find("xvfb-run"), std::string::npos) << output;
  EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
  expect_clean(run);
}
}  // namespace
}  // namespace l2
