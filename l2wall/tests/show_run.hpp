// Shared by the --show tests: a private Xvfb big enough for the default wall at native size,
// the wall window's title, and waiting on what a live run prints (its files: wall_run.hpp).
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "displays/xvfb_server.hpp"
#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2::testing_support {

// Starts Xvfb with a screen of the given size (DISPLAY points at it), or skips the test.
#define L2_START_XVFB(server, width, height)                                            \
  if (!::l2::testing::XvfbServer::installed()) GTEST_SKIP() << "Xvfb is not installed"; \
  ::l2::testing::XvfbServer server(width, height)

// The default wall: 2x2 displays of 640x480 with 20-pixel mullions, 1300x980 in all, plus the
// overlay bar: the screen leaves room for it at native scale.
constexpr int kScreenW = 1400, kScreenH = 1100;
inline const std::string kTitle = "l2wall - 2x2 k-d wall";
constexpr Rgb kMullion{24, 24, 28};  // displays/colours.hpp, written out: the test's own claim

// A small wall for the key tests, cheap to render on a loaded machine: two 320x240 displays
// side by side, 16 pixels apart, fed by two pipeservers.
inline const std::string kSmallTitle = "l2wall - two displays";
inline fs::path write_small_wall(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = dir / "two.toml";
  std::ofstream(file) << R"(name = "two displays"
[display_grid]
columns = 2
rows = 1
width = 320
height = 240
mullion_x = 16
[tiling]
kind = "grid"
tile_width = 160
tile_height = 120
[pipeservers]
count = 2
framebuffer_width = 400
framebuffer_height = 300
)";
  return file;
}

inline RgbImage display_png(const fs::path& dir, int frame, int display,
                            const std::string& prefix = "") {
  return read_png(dir / fmt::format("frame-{}", frame) /
                  fmt::format("{}display-{}.png", prefix, display));
}

// Lines the pipeservers logged so far: one per frame they published.
inline std::vector<int> pipeserver_lines(const WallRun& run, int pipeservers) {
  std::vector<int> lines;
  for (int s = 0; s < pipeservers; ++s) lines.push_back(run.pipeserver_frames_logged(s));
  return lines;
}

// Waits until `pattern` matches the run's output; returns the first group, -1 on timeout.
inline int wait_for_output(const WallRun& run, const std::string& pattern,
                           std::chrono::seconds timeout) {
  const std::regex re(pattern);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    std::smatch m;
    const std::string out = run.output();
    if (std::regex_search(out, m, re)) return std::stoi(m[1]);
    if (std::chrono::steady_clock::now() >= deadline) return -1;
    std::this_thread::sleep_for(20ms);
  }
}

}  // namespace l2::testing_support
