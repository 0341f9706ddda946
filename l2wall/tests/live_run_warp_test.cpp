// Geometry warps end to end (docs/wall-file.md, "Warping projected pictures"): a user's run
// through `l2wall run` on a wall whose two displays each have a warp written here, a picture of
// positions shown at 1:1, and every saved pixel of both paths against what the documented rule
// gives, worked out here: display 0 mirrored, its top rows NaN (black), from a PFM of one point
// per pixel; display 1 shifted half a pixel to the right, from a 2x2 mesh.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>

#include "grey_png.hpp"
#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kWidth = 320, kHeight = 240, kBlackRows = 10;

// Canvas pixel (x, y) as a colour that names it.
Rgb position(int x, int y) {
  return {static_cast<std::uint8_t>(x & 255), static_cast<std::uint8_t>(y & 255),
          static_cast<std::uint8_t>((x >> 8 & 15) | (y >> 8 & 15) << 4)};
}

// Pixel i's centre on a side of `size` pixels, normalised.
float centre(int i, int size) {
  return (static_cast<float>(i) + 0.5f) / static_cast<float>(size);
}

// A PFM of w x h points, little-endian, rows bottom first; `at(i, j)` gives point (i, j)'s
// normalised (x, y), j counted from the top.
template <class At>
void write_pfm(const fs::path& path, int w, int h, At at) {
  std::ofstream out(path, std::ios::binary);
  out << fmt::format("PF\n{} {}\n-1.0\n", w, h);
  for (int j = h - 1; j >= 0; --j) {
    for (int i = 0; i < w; ++i) {
      const auto [x, y] = at(i, j);
      for (const float v : {x, y, 0.0f}) {
        const auto bits = std::bit_cast<std::uint32_t>(v);
        for (int b = 0; b < 4; ++b) out.put(static_cast<char>(bits >> (8 * b) & 0xff));
      }
    }
  }
}

const std::string kWall = R"(name = "two warped displays"
[[display]]
width = 320
height = 240
x = 0
y = 0
warp = "mirror.pfm"
[[display]]
width = 320
height = 240
x = 320
y = 0
warp = "shift.pfm"
[tiling]
kind = "grid"
tile_width = 160
tile_height = 120
[pipeservers]
count = 2
framebuffer_width = 400
framebuffer_height = 400
)";

// The documented mix of two pixels half a pixel apart: (a * 128 + b * 128) * 256, plus 1/2,
// over 65536; (a + b + 1) / 2 in integers.
Rgb halfway(Rgb a, Rgb b) {
  const auto mix = [](int p, int q) { return static_cast<std::uint8_t>((p + q + 1) / 2); };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

TEST(LiveRunWarp, SavedDisplaysAreTheFrameWarpedAsDocumented) {
  const ScratchDir dir("warp");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  write_pfm(dir / "mirror.pfm", kWidth, kHeight, [&](int i, int j) {
    if (j < kBlackRows) return std::pair(nan, nan);
    return std::pair(centre(kWidth - 1 - i, kWidth), centre(j, kHeight));
  });
  // The corners of a shift by half a pixel: points on the first and last pixel centres show
  // x + 1/2, normalised (x + 1) / width; the last column's falls past the last centre and is
  // clamped to it.
  write_pfm(dir / "shift.pfm", 2, 2, [&](int i, int j) {
    const int x = i * (kWidth - 1), y = j * (kHeight - 1);
    return std::pair(static_cast<float>(x + 1) / kWidth, centre(y, kHeight));
  });
  std::ofstream(dir / "wall.toml") << kWall;
  RgbImage canvas(2 * kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < 2 * kWidth; ++x) canvas.set(x, y, position(x, y));
  write_png(dir / "positions.png", canvas);

  WallRun run("warp", {"--wall", (dir / "wall.toml").string(), "--scene", "picture", "--content",
                       (dir / "positions.png").string(), "--fit", "stretch", "--frames", "3",
                       "--refresh", "0", "--path", "both", "--compare", "--keep", "every"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_NE(run.output().find("compare: 6 display pictures identical byte for byte"),
            std::string::npos)
      << run.output();
  long wrong = 0;
  for (const char* path : {"", "-vizserver"}) {
    const fs::path frame = run.out() / "frame-2";
    const RgbImage zero = read_png(frame / fmt::format("display-0{}.png", path));
    const RgbImage one = read_png(frame / fmt::format("display-1{}.png", path));
    ASSERT_EQ(zero.width(), kWidth);
    ASSERT_EQ(one.width(), kWidth);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const Rgb mirrored = y < kBlackRows ? Rgb{} : position(kWidth - 1 - x, y);
        wrong += !(zero.at(x, y) == mirrored);
        const int u = kWidth + x;  // display 1's canvas column
        const Rgb shifted =
            x == kWidth - 1 ? position(u, y) : halfway(position(u, y), position(u + 1, y));
        wrong += !(one.at(x, y) == shifted);
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  // Spot checks of the rule, in numbers: display 1's pixel (0, 20) mixes canvas (320, 20) =
  // (64, 20, 1) and (321, 20) = (65, 20, 1): red (64 + 65 + 1) / 2 = 65.
  const RgbImage one = read_png(run.out() / "frame-2" / "display-1.png");
  EXPECT_EQ(one.at(0, 20), (Rgb{65, 20, 1}));
  const RgbImage zero = read_png(run.out() / "frame-2" / "display-0.png");
  EXPECT_EQ(zero.at(0, 20), (Rgb{63, 20, 1}));  // canvas (319, 20)
  EXPECT_EQ(zero.at(5, 5), (Rgb{0, 0, 0}));
  expect_clean(run);
}

// Alpha and beta maps end to end (docs/wall-file.md, "Alpha and beta maps"): display 0 mirrored
// by its warp and then weighted by an alpha map that falls from 255 at its left column to 0 at
// its right, at alpha_gamma 2.2; display 1 with a beta map of 40 in its top half. Every saved
// pixel of both paths against the documented rule, worked out here.
TEST(LiveRunWarp, AlphaAndBetaMapsApplyAfterTheWarpAsDocumented) {
  const ScratchDir dir("levels");
  write_pfm(dir / "mirror.pfm", kWidth, kHeight, [&](int i, int j) {
    return std::pair(centre(kWidth - 1 - i, kWidth), centre(j, kHeight));
  });
  std::vector<std::uint8_t> alpha, beta;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      alpha.push_back(static_cast<std::uint8_t>(255 - x * 255 / (kWidth - 1)));
      beta.push_back(y < kHeight / 2 ? 40 : 0);
    }
  }
  write_grey_png(dir / "alpha.png", kWidth, kHeight, alpha);
  write_grey_png(dir / "beta.png", kWidth, kHeight, beta);
  std::string wall = kWall;
  wall.replace(wall.find("warp = \"shift.pfm\""), 18, "beta = \"beta.png\"");
  wall.replace(wall.find("warp = \"mirror.pfm\""), 19,
               "warp = \"mirror.pfm\"\nalpha = \"alpha.png\"\nalpha_gamma = 2.2");
  std::ofstream(dir / "wall.toml") << wall;
  RgbImage canvas(2 * kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < 2 * kWidth; ++x) canvas.set(x, y, position(x, y));
  write_png(dir / "positions.png", canvas);

  WallRun run("levels", {"--wall", (dir / "wall.toml").string(), "--scene", "picture", "--content",
                         (dir / "positions.png").string(), "--fit", "stretch", "--frames", "3",
                         "--refresh", "0", "--path", "both", "--compare", "--keep", "every"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  // The rule: gain = round(a^(1/gamma) * (1 - b) * 65536), offset = round(b * 255 * 65536),
  // out = (in * gain + offset + 32768) / 65536 rounded down, a and b the maps' bytes / 255.
  const auto level = [](Rgb in, int a, double gamma, int b) {
    const double fa = a / 255.0, fb = b / 255.0;
    const auto gain =
        static_cast<long long>(std::floor(std::pow(fa, 1 / gamma) * (1 - fb) * 65536 + 0.5));
    const auto offset = static_cast<long long>(std::floor(fb * 255 * 65536 + 0.5));
    const auto one = [&](int v) {
      return static_cast<std::uint8_t>((v * gain + offset + 32768) >> 16);
    };
    return Rgb{one(in.r), one(in.g), one(in.b)};
  };
  long wrong = 0;
  for (const char* path : {"", "-vizserver"}) {
    const fs::path frame = run.out() / "frame-2";
    const RgbImage zero = read_png(frame / fmt::format("display-0{}.png", path));
    const RgbImage one = read_png(frame / fmt::format("display-1{}.png", path));
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
        wrong += !(zero.at(x, y) == level(position(kWidth - 1 - x, y), alpha[i], 2.2, 0));
        wrong += !(one.at(x, y) == level(position(kWidth + x, y), 255, 1.0, beta[i]));
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  // In numbers: display 0's right column has alpha 0 (black); display 1's pixel (0, 0) shows
  // canvas (320, 0) = (64, 0, 1) raised by beta 40: 40 + 64 * 215/255 = 93.96 -> 94, 40, 40.8.
  const RgbImage zero = read_png(run.out() / "frame-2" / "display-0.png");
  EXPECT_EQ(zero.at(kWidth - 1, 100), (Rgb{0, 0, 0}));
  const RgbImage one = read_png(run.out() / "frame-2" / "display-1.png");
  EXPECT_EQ(one.at(0, 0), (Rgb{94, 40, 41}));
  EXPECT_EQ(one.at(0, kHeight - 1), position(kWidth, kHeight - 1));
  expect_clean(run);
}

}  // namespace
}  // namespace l2
