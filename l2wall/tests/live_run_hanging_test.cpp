// What a person in front of the wall sees, in a user's run through `l2wall run`, on both paths:
// no frame stamp marks a picture (issue 56: the stamps ride in the stamp strips, which no display
// shows), and panels that hang turned or mirrored show the canvas as the wall file's mapping
// says (docs/wall-file.md), every pixel, the expected pixels worked out here from the wall
// file's numbers.
#include <gtest/gtest.h>

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
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-grey-{}", getpid());
  fs::create_directories(dir);
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
  fs::remove_all(dir);
}

// Canvas pixel (x, y) as a colour that names it.
Rgb position(int x, int y) {
  return {static_cast<std::uint8_t>(x & 255), static_cast<std::uint8_t>(y & 255),
          static_cast<std::uint8_t>((x >> 8 & 15) | (y >> 8 & 15) << 4)};
}

TEST(LiveRunHanging, TurnedAndMirroredPanelsShowTheCanvasAsDocumented) {
  // walls/mixed-hang.toml: 1280x720 panels; display 0 as it is at 0,0; display 1 at 270 at
  // 1320,0 (720x1280 on the canvas); display 2 at 180 and flipped horizontally at 0,760.
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-hang-{}", getpid());
  fs::create_directories(dir);
  RgbImage canvas(2040, 1480);
  for (int y = 0; y < canvas.height(); ++y)
    for (int x = 0; x < canvas.width(); ++x) canvas.set(x, y, position(x, y));
  write_png(dir / "positions.png", canvas);
  WallRun run("hang",
              {"--wall", (fs::path(L2_SOURCE_DIR) / "walls/mixed-hang.toml").string(), "--scene",
               "picture", "--content", (dir / "positions.png").string(), "--fit", "stretch",
               "--frames", "2", "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const auto expected = [](int d, int x, int y) {
    if (d == 1) return position(1320 + y, 1279 - x);  // 270: (x0 + y, y0 + ch - 1 - x)
    if (d == 2) return position(x, 760 + 719 - y);    // flip: x -> 1279 - x; 180: back again
    return position(x, y);
  };
  EXPECT_EQ(wrong_pixels(run, 1, 3, expected), 0);
  expect_clean(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
