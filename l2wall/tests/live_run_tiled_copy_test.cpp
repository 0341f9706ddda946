// A PNG too large to hold decoded (past a threshold lowered here through L2_TILED_COPY_MB)
// through `l2wall run`: copied once into a tiled TIFF with MIP levels in the folder of copies
// ($XDG_CACHE_HOME here) before the pipeservers start, saying how far it has got; a second run
// finds the copy and says so; and at a fixed 1:1 view (--pan, --zoom 1) every display pixel is
// the PNG's own, worked out here from the PNG's formula.
#include <stdlib.h>

#include <algorithm>
#include <cmath>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;
using namespace std::chrono_literals;

constexpr int kWidth = 2600, kHeight = 1960;  // 14.6 MiB decoded

Rgb source(long x, long y) {
  return {static_cast<std::uint8_t>(x * 5), static_cast<std::uint8_t>(y * 3),
          static_cast<std::uint8_t>((x >> 4) + (y >> 4))};
}

// Display pixels of frame `frame` that are not the PNG's pixel at 1:1 with picture pixel
// (cx, cy) at the canvas's centre, each pipeserver's frame stamp aside.
long wrong_at_one_to_one(const WallRun& run, int frame, double cx, double cy) {
  const Wall wall = default_wall();
  return wrong_canvas_pixels(run, wall, frame, [&](int u, int v) {
    const auto sx = static_cast<long>(std::floor(cx + (u + 0.5 - wall.canvas_width / 2.0)));
    const auto sy = static_cast<long>(std::floor(cy + (v + 0.5 - wall.canvas_height / 2.0)));
    const bool inside = sx >= 0 && sx < kWidth && sy >= 0 && sy < kHeight;
    return inside ? source(sx, sy) : Rgb{};
  });
}

TEST(TiledCopyRun, ALargePngIsCopiedOnceBeforeThePipeserversAndShownAsItIs) {
  const fs::path dir = WallRun::folder_for("tiled-copy-files");
  fs::create_directories(dir);
  const fs::path png = dir / "large-scanlines.png";
  {
    RgbImage picture(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) picture.set(x, y, source(x, y));
    write_png(png, picture);
  }
  setenv("XDG_CACHE_HOME", (dir / "cache").c_str(), 1);
  setenv("L2_TILED_COPY_MB", "4", 1);
  const std::vector<std::string> args = {"--scene",   "picture", "--content", png.string(), "--pan",
                                         "1000,700",  "--zoom",  "1",         "--frames",   "2",
                                         "--refresh", "0",       "--keep",    "every"};
  const fs::path copies = dir / "cache" / "lightning2" / "pictures";
  {
    WallRun first("tiled-copy-first", args);
    const ExitStatus status = first.wait(120s);
    ASSERT_TRUE(status.ok()) << status.describe() << "\n" << first.output();
    EXPECT_NE(first.output().find("converting large-scanlines.png (2600x1960) into a tiled "
                                  "picture with mip levels: 100%"),
              std::string::npos)
        << first.output();
    EXPECT_EQ(std::distance(fs::directory_iterator(copies), fs::directory_iterator()), 1);
    EXPECT_EQ(wrong_at_one_to_one(first, 1, 1000, 700), 0);
  }
  {
    WallRun second("tiled-copy-second", args);
    const ExitStatus status = second.wait(120s);
    ASSERT_TRUE(status.ok()) << status.describe() << "\n" << second.output();
    EXPECT_NE(second.output().find("made earlier"), std::string::npos) << second.output();
    EXPECT_EQ(second.output().find("converting"), std::string::npos) << second.output();
    EXPECT_EQ(wrong_at_one_to_one(second, 0, 1000, 700), 0);
  }
  unsetenv("L2_TILED_COPY_MB");
  unsetenv("XDG_CACHE_HOME");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
