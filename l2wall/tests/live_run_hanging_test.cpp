// What a person in front of the wall sees, in a user's run through `l2wall run`, on both paths:
// no frame stamp marks a picture (issue 56: the stamps ride in the stamp strips, which no display
// shows); panels that hang turned or mirrored show the canvas as the wall file's mapping says
// (docs/wall-file.md); colour-matched panels show it through their tables. Every pixel, the
// expected ones worked out here from the wall files' numbers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// Pixels of the kept display pictures of frame `frame`, both paths, that are not `expected(d,
// x, y)`.
template <class Expected>
long wrong_pixels(const WallRun& run, int frame, int displays, Expected expected) {
  long wrong = 0;
  for (int d = 0; d < displays; ++d) {
    for (const char* path : {"", "-vizserver"}) {
      const RgbImage shown = read_png(run.out() / fmt::format("frame-{}", frame) /
                                      fmt::format("display-{}{}.png", d, path));
      for (int y = 0; y < shown.height(); ++y)
        for (int x = 0; x < shown.width(); ++x) wrong += !(shown.at(x, y) == expected(d, x, y));
    }
  }
  return wrong;
}

TEST(LiveRunHanging, AGreyPictureOnTheProjectorsShowsNoStampDot) {
  const ScratchDir dir("grey");
  write_png(dir / "grey.png", RgbImage(64, 48, Rgb{128, 128, 128}));
  WallRun run("grey",
              {"--wall", (fs::path(L2_SOURCE_DIR) / "walls/projectors-2x1.toml").string(),
               "--scene", "picture", "--content", (dir / "grey.png").string(), "--fit", "stretch",
               "--frames", "3", "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_NE(run.output().find("latency: 1 frame "), std::string::npos) << run.output();
  EXPECT_EQ(wrong_pixels(run, 2, 2, [](int, int, int) { return Rgb{128, 128, 128}; }), 0);
  expect_clean(run);
}

// The acceptance test of edge blending (walls/projectors-2x1-blended.toml: 1024x768
// projectors, display 1 at canvas column 960, blend gamma 2.2): a uniform grey picture, and over
// the 64 overlap columns the two projectors' light, (a/255)^2.2 + (b/255)^2.2, taken back to a
// code value, is the picture's 128 within one; everywhere else each shows 128 as it is; both
// paths the same bytes.
TEST(LiveRunHanging, BlendedProjectorsAddUpToThePictureInLinearLight) {
  const ScratchDir dir("blend");
  write_png(dir / "grey.png", RgbImage(64, 48, Rgb{128, 128, 128}));
  WallRun run("blend",
              {"--wall", (fs::path(L2_SOURCE_DIR) / "walls/projectors-2x1-blended.toml").string(),
               "--scene", "picture", "--content", (dir / "grey.png").string(), "--fit", "stretch",
               "--frames", "3", "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const double gamma = 2.2;
  const fs::path frame = run.out() / "frame-2";
  const RgbImage zero = read_png(frame / "display-0.png"), one = read_png(frame / "display-1.png");
  ASSERT_EQ(zero.width(), 1024);
  ASSERT_EQ(one.width(), 1024);
  EXPECT_TRUE(read_png(frame / "display-0-vizserver.png") == zero);
  EXPECT_TRUE(read_png(frame / "display-1-vizserver.png") == one);
  long outside_wrong = 0, overlap_wrong = 0;
  double worst = 0;
  for (int y = 0; y < 768; ++y) {
    for (int x = 0; x < 960; ++x) {
      outside_wrong += !(zero.at(x, y) == Rgb{128, 128, 128});
      outside_wrong += !(one.at(x + 64, y) == Rgb{128, 128, 128});
    }
    for (int u = 960; u < 1024; ++u) {
      const Rgb a = zero.at(u, y), b = one.at(u - 960, y);
      for (const auto& [ca, cb] : {std::pair{a.r, b.r}, std::pair{a.g, b.g}, std::pair{a.b, b.b}}) {
        const double light = std::pow(ca / 255.0, gamma) + std::pow(cb / 255.0, gamma);
        const double miss = std::abs(255 * std::pow(light, 1 / gamma) - 128);
        worst = std::max(worst, miss);
        overlap_wrong += miss > 1;
      }
    }
  }
  EXPECT_EQ(outside_wrong, 0);
  EXPECT_EQ(overlap_wrong, 0) << "worst " << worst;
  // Each ramps down toward its own edge: at its last column a weight of 0.5/64, so 128 *
  // (1/128)^(1/2.2) = 14.1; at the overlap's far side 63.5/64, 128 * 0.9965 = 127.5.
  EXPECT_LT(zero.at(1023, 0).r, 20);
  EXPECT_GE(zero.at(960, 0).r, 127);
  EXPECT_LT(one.at(0, 0).r, 20);
  expect_clean(run);
}

// Canvas pixel (x, y) as a colour that names it.
Rgb position(int x, int y) {
  return {static_cast<std::uint8_t>(x & 255), static_cast<std::uint8_t>(y & 255),
          static_cast<std::uint8_t>((x >> 8 & 15) | (y >> 8 & 15) << 4)};
}

// A canvas-sized picture of positions, shown at 1:1 with --fit stretch.
std::string write_positions(const ScratchDir& dir, int width, int height) {
  RgbImage canvas(width, height);
  for (int y = 0; y < canvas.height(); ++y)
    for (int x = 0; x < canvas.width(); ++x) canvas.set(x, y, position(x, y));
  write_png(dir / "positions.png", canvas);
  return (dir / "positions.png").string();
}

TEST(LiveRunHanging, TurnedAndMirroredPanelsShowTheCanvasAsDocumented) {
  // walls/mixed-hang.toml: 1280x720 panels; display 0 as it is at 0,0; display 1 at 270 at
  // 1320,0 (720x1280 on the canvas); display 2 at 180 and flipped horizontally at 0,760.
  const ScratchDir dir("hang");
  const std::string positions = write_positions(dir, 2040, 1480);
  WallRun run("hang", {"--wall", (fs::path(L2_SOURCE_DIR) / "walls/mixed-hang.toml").string(),
                       "--scene", "picture", "--content", positions, "--fit", "stretch", "--frames",
                       "2", "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const auto expected = [](int d, int x, int y) {
    if (d == 1) return position(1320 + y, 1279 - x);  // 270: (x0 + y, y0 + ch - 1 - x)
    if (d == 2) return position(x, 760 + 719 - y);    // flip: x -> 1279 - x; 180: back again
    return position(x, y);
  };
  EXPECT_EQ(wrong_pixels(run, 1, 3, expected), 0);
  expect_clean(run);
}

// The position picture at 1:1 on the colour-matched wall (walls/colour-matched-2x2.toml: 320x240
// panels, 10-pixel mullions): each display pixel is its canvas pixel through the display's
// tables, worked out here from the wall file's numbers and the table file's lines: display 0 by
// gain [1.0, 0.96, 0.92] and offset [0, 0, 4] (docs/wall-file.md: G = round(gain x 2^32), out =
// clamp(floor((in G + 2^31) / 2^32) + offset, 0, 255)), display 2 by calibration/panel-2.txt,
// displays 1 and 3 as they are.
TEST(LiveRunHanging, ColourMatchedPanelsShowTheCanvasThroughTheirTables) {
  const fs::path walls = fs::path(L2_SOURCE_DIR) / "walls";
  std::array<std::array<std::uint8_t, 256>, 3> gained{}, measured{};
  // 1.0, 0.96 and 0.92 of 2^32, rounded.
  const std::int64_t gains[3] = {4294967296, 4123168604, 3951369912};
  const int offsets[3] = {0, 0, 4};
  for (int c = 0; c < 3; ++c)
    for (std::int64_t v = 0; v < 256; ++v)
      gained[c][v] = static_cast<std::uint8_t>(std::clamp<std::int64_t>(
          ((v * gains[c] + (std::int64_t{1} << 31)) >> 32) + offsets[c], 0, 255));
  std::ifstream table(walls / "calibration/panel-2.txt");
  int entry = 0;
  for (std::string line; std::getline(table, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    int r = 0, g = 0, b = 0;
    words >> r >> g >> b;
    ASSERT_LT(entry, 256);
    measured[0][entry] = static_cast<std::uint8_t>(r);
    measured[1][entry] = static_cast<std::uint8_t>(g);
    measured[2][entry] = static_cast<std::uint8_t>(b);
    ++entry;
  }
  ASSERT_EQ(entry, 256);

  const ScratchDir dir("matched");
  const std::string positions = write_positions(dir, 650, 490);
  WallRun run("matched", {"--wall", (walls / "colour-matched-2x2.toml").string(), "--scene",
                          "picture", "--content", positions, "--fit", "stretch", "--frames", "2",
                          "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const auto expected = [&](int d, int x, int y) {
    const Rgb p = position(330 * (d % 2) + x, 250 * (d / 2) + y);
    if (d == 1 || d == 3) return p;
    const auto& t = d == 0 ? gained : measured;
    return Rgb{t[0][p.r], t[1][p.g], t[2][p.b]};
  };
  EXPECT_EQ(wrong_pixels(run, 1, 4, expected), 0);
  expect_clean(run);
}

}  // namespace
}  // namespace l2
