// A picture stored as scanlines past the copy threshold (lowered here through
// L2_TILED_COPY_MB) shown by the picture scene: its tiled copy appears in the folder of copies
// ($XDG_CACHE_HOME here) with MIP levels, each level the 2x2 mean of the one before (worked
// out here from the picture's pixels), a second scene reuses it and says so, and at 1:1 the
// routed displays hold the picture's own pixels.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "image/png_io.hpp"
#include "image/tiled_copy.hpp"
#include "pipeserver/picture_view.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

constexpr int kSourceWidth = 600, kSourceHeight = 400;  // 0.69 MiB decoded

Rgb source_pixel(int x, int y) {
  return {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 3),
          static_cast<std::uint8_t>((x ^ y) & 255)};
}

long shown_index(double centre, double scale, int size, int x) {
  return static_cast<long>(std::floor(centre + (x + 0.5 - size / 2.0) * scale));
}

class TiledCopy : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("tiled-copy-{}", getpid());
    fs::create_directories(dir_);
    setenv("XDG_CACHE_HOME", (dir_ / "cache").c_str(), 1);
    setenv(kTiledCopyThresholdVariable, "0.5", 1);
    RgbImage picture(kSourceWidth, kSourceHeight);
    for (int y = 0; y < kSourceHeight; ++y)
      for (int x = 0; x < kSourceWidth; ++x) picture.set(x, y, source_pixel(x, y));
    write_png(dir_ / "scanlines.png", picture);
  }
  void TearDown() override {
    unsetenv(kTiledCopyThresholdVariable);
    unsetenv("XDG_CACHE_HOME");
    fs::remove_all(dir_);
  }
  std::vector<fs::path> copies() const {
    std::vector<fs::path> found;
    const fs::path folder = dir_ / "cache" / "lightning2" / "pictures";
    if (!fs::exists(folder)) return found;
    for (const auto& e : fs::directory_iterator(folder)) found.push_back(e.path());
    return found;
  }
  fs::path dir_;
};

TEST_F(TiledCopy, IsMadeOnceWithLevelsAndShowsThePicturesPixels) {
  SceneOptions options;
  options.content = dir_ / "scanlines.png";
  testing::internal::CaptureStderr();
  auto scene = make_scene("picture", options);
  const std::string first = testing::internal::GetCapturedStderr();
  EXPECT_NE(first.find("converting scanlines.png (600x400) into a tiled picture with mip levels: "
                       "100%"),
            std::string::npos)
      << first;
  const std::vector<fs::path> made = copies();
  ASSERT_EQ(made.size(), 1u);

  // The copy: tiled, a level a halving down to 1x1, level 1 the mean of level 0's pairs.
  auto in = OIIO::ImageInput::open(made[0].string());
  ASSERT_TRUE(in);
  EXPECT_GT(in->spec().tile_width, 0);
  int levels = 0;
  while (in->seek_subimage(0, levels)) ++levels;
  EXPECT_EQ(levels, 10);  // 600x400, 300x200, ... 4x3, 2x1, 1x1
  ASSERT_TRUE(in->seek_subimage(0, 1));
  std::vector<std::uint8_t> level1(300 * 200 * 3);
  ASSERT_TRUE(in->read_image(0, 1, 0, 3, OIIO::TypeDesc::UINT8, level1.data()));
  long wrong = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 300; ++x) {
      const Rgb a = source_pixel(2 * x, 2 * y), b = source_pixel(2 * x + 1, 2 * y),
                c = source_pixel(2 * x, 2 * y + 1), d = source_pixel(2 * x + 1, 2 * y + 1);
      const std::uint8_t* got = &level1[static_cast<std::size_t>(3 * (y * 300 + x))];
      wrong += got[0] != (a.r + b.r + c.r + d.r + 2) / 4 ||
               got[1] != (a.g + b.g + c.g + d.g + 2) / 4 ||
               got[2] != (a.b + b.b + c.b + d.b + 2) / 4;
    }
  }
  EXPECT_EQ(wrong, 0);

  // A second scene finds it.
  testing::internal::CaptureStderr();
  make_scene("picture", options);
  const std::string second = testing::internal::GetCapturedStderr();
  EXPECT_NE(second.find("using the tiled copy " + made[0].string() + " made earlier"),
            std::string::npos)
      << second;
  EXPECT_EQ(copies(), made);

  // At 1:1 the displays hold the picture's pixels.
  const TileLayout layout = test::small_layout(3, 40, 20, 120, 120);
  const Canvas canvas = canvas_of(layout.wall);
  const int frame = kPictureZoomPeriod / 2;
  std::vector<RgbImage> frames;
  for (int s = 0; s < 3; ++s) frames.push_back(Pipeserver(layout, s).render_frame(frame, *scene));
  const auto r = test::reassemble(layout.wall, frames);
  const SourceView v = picture_view(frame, kSourceWidth, kSourceHeight, canvas);
  long off = 0;
  for (const Display& d : layout.wall.displays) {
    const RgbImage& shown = r.displays[static_cast<std::size_t>(d.id)];
    const Rect on = d.on_canvas();
    for (int y = 0; y < shown.height(); ++y) {
      const long sy = shown_index(v.centre_y, v.scale_y, canvas.height, on.y + y);
      for (int x = 0; x < shown.width(); ++x) {
        const long sx = shown_index(v.centre_x, v.scale_x, canvas.width, on.x + x);
        off += !(shown.at(x, y) == source_pixel(static_cast<int>(sx), static_cast<int>(sy)));
      }
    }
  }
  EXPECT_EQ(off, 0);
}

TEST_F(TiledCopy, APictureUnderTheThresholdIsReadItself) {
  setenv(kTiledCopyThresholdVariable, "1", 1);
  EXPECT_EQ(picture_to_read(dir_ / "scanlines.png", 512), dir_ / "scanlines.png");
  EXPECT_TRUE(copies().empty());
}

TEST(TiledCopyName, DependsOnPathSizeAndTime) {
  const std::string a = tiled_copy_name("/p/big.png", 100, 5);
  EXPECT_EQ(a.substr(0, 4), "big-");
  EXPECT_EQ(a.substr(a.size() - 4), ".tif");
  EXPECT_EQ(a, tiled_copy_name("/p/big.png", 100, 5));
  EXPECT_NE(a, tiled_copy_name("/q/big.png", 100, 5));
  EXPECT_NE(a, tiled_copy_name("/p/big.png", 101, 5));
  EXPECT_NE(a, tiled_copy_name("/p/big.png", 100, 6));
}

}  // namespace
}  // namespace l2
