// The picture scene on a file with MIP levels: a tiled TIFF pyramid written here, each level's
// pixels saying their level, column and row, so a routed display shows which level and which
// pixel of it every canvas pixel took; the level and pixel expected are worked out here from
// the rule in picture_view.hpp, not by its functions. A file whose levels do not halve is one
// line. Links OpenImageIO itself, to write the pyramids: not under the sanitizers.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "pipeserver/picture_view.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

// Eight times the small wall's 136x48 canvas: frame 0's view has 8 picture pixels a canvas
// pixel on both axes.
constexpr int kWidth = 1088, kHeight = 384;

// Level, column and row in one colour: red the level and the high bits, green and blue the low.
Rgb level_pixel(int level, int x, int y) {
  return {static_cast<std::uint8_t>(level * 32 + (x >> 8) * 2 + (y >> 8)),
          static_cast<std::uint8_t>(x & 255), static_cast<std::uint8_t>(y & 255)};
}

struct Side {
  int width, height;
};

// A tiled TIFF whose level l is sides[l], each pixel level_pixel of its own level. As maketx
// writes one: a directory a level, the first marked a texture, which is what makes OpenImageIO
// read the others as its levels rather than as pages.
void write_pyramid(const fs::path& path, const std::vector<Side>& sides) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  for (std::size_t l = 0; l < sides.size(); ++l) {
    OIIO::ImageSpec spec(sides[l].width, sides[l].height, 3, OIIO::TypeDesc::UINT8);
    spec.tile_width = spec.tile_height = 64;
    if (l == 0) spec.attribute("textureformat", "Plain Texture");
    const auto mode = l == 0 ? OIIO::ImageOutput::Create : OIIO::ImageOutput::AppendSubimage;
    ASSERT_TRUE(out->open(path.string(), spec, mode)) << out->geterror();
    std::vector<std::uint8_t> pixels;
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const Rgb p = level_pixel(static_cast<int>(l), x, y);
        pixels.insert(pixels.end(), {p.r, p.g, p.b});
      }
    }
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data())) << out->geterror();
  }
  ASSERT_TRUE(out->close());
}

std::vector<Side> halvings(int levels) {
  std::vector<Side> sides{{kWidth, kHeight}};
  while (static_cast<int>(sides.size()) < levels) {
    sides.push_back({std::max(1, sides.back().width / 2), std::max(1, sides.back().height / 2)});
  }
  return sides;
}

long sampled(double centre, double scale, int size, int x) {
  return static_cast<long>(std::floor(centre + (x + 0.5 - size / 2.0) * scale));
}

// What a test expects a view to show: the picture pixel at the canvas's centre and picture
// pixels per canvas pixel, worked out by the test.
struct Expected {
  double centre_x, centre_y, scale;
};

// Counts the display pixels of frame `frame` of `options`' picture scene that are not the
// pixel the rule names: level L the largest with 2^L <= the scale, at most the file's last;
// that level's pixel under the picture's, black outside the picture.
long wrong_pixels(const SceneOptions& options, const std::vector<Side>& sides, int frame,
                  const Expected& v, int* level_seen) {
  auto scene = make_scene("picture", options);
  const TileLayout layout = test::small_layout(3, 40, 20, 120, 120);
  const Canvas canvas = canvas_of(layout.wall);
  std::vector<RgbImage> frames;
  for (int s = 0; s < 3; ++s) frames.push_back(Pipeserver(layout, s).render_frame(frame, *scene));
  const auto r = test::reassemble(layout.wall, frames);
  EXPECT_EQ(r.errors.total(), 0u);
  int level = 0;
  const int last = static_cast<int>(sides.size()) - 1;
  while (level < last && (2 << level) <= v.scale) ++level;
  *level_seen = level;
  const Side side = sides[static_cast<std::size_t>(level)];
  long wrong = 0;
  for (const Display& d : layout.wall.displays) {
    const RgbImage& shown = r.displays[static_cast<std::size_t>(d.id)];
    const Rect on = d.on_canvas();
    for (int y = 0; y < shown.height(); ++y) {
      const long sy = sampled(v.centre_y, v.scale, canvas.height, on.y + y);
      const int ly = std::min(static_cast<int>(sy >> level), side.height - 1);
      for (int x = 0; x < shown.width(); ++x) {
        const long sx = sampled(v.centre_x, v.scale, canvas.width, on.x + x);
        const int lx = std::min(static_cast<int>(sx >> level), side.width - 1);
        const bool inside = sx >= 0 && sx < kWidth && sy >= 0 && sy < kHeight;
        wrong += !(shown.at(x, y) == (inside ? level_pixel(level, lx, ly) : Rgb{0, 0, 0}));
      }
    }
  }
  return wrong;
}

// The same for the animated path's frame `frame`, its view from picture_view.
long wrong_pixels(const fs::path& file, const std::vector<Side>& sides, int frame,
                  int* level_seen) {
  SceneOptions options;
  options.content = file;
  const SourceView v =
      picture_view(frame, kWidth, kHeight, canvas_of(test::small_layout(3, 40, 20, 120, 120).wall));
  EXPECT_DOUBLE_EQ(v.scale_x, v.scale_y);
  return wrong_pixels(options, sides, frame, {v.centre_x, v.centre_y, v.scale_x}, level_seen);
}

fs::path scratch(const char* name) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("{}-{}", name, getpid());
  fs::create_directories(dir);
  return dir;
}

TEST(PictureLevels, ZoomedOutTheDisplaysShowTheLevelTheRuleNames) {
  const fs::path dir = scratch("picture-levels");
  const std::vector<Side> sides = halvings(5);
  write_pyramid(dir / "pyramid.tif", sides);
  // Frame 0: 8 picture pixels a canvas pixel, level 3; a quarter period on, 2.83, level 1; at
  // half the period 1:1, level 0.
  for (const auto& [frame, want_level] : {std::pair{0, 3}, std::pair{kPictureZoomPeriod / 4, 1},
                                          std::pair{kPictureZoomPeriod / 2, 0}}) {
    int level = -1;
    EXPECT_EQ(wrong_pixels(dir / "pyramid.tif", sides, frame, &level), 0) << "frame " << frame;
    EXPECT_EQ(level, want_level) << "frame " << frame;
  }
  fs::remove_all(dir);
}

// --pan X,Y --zoom Z: picture pixel (X, Y) at the canvas's centre, 1 / Z picture pixels a
// canvas pixel, the same at every frame; a quarter shows level 2; with the centre at the
// picture's corner, three quarters of the canvas black.
TEST(PictureLevels, AFixedViewShowsTheLevelRegionItNames) {
  const fs::path dir = scratch("picture-fixed");
  const std::vector<Side> sides = halvings(5);
  write_pyramid(dir / "pyramid.tif", sides);
  SceneOptions options;
  options.content = dir / "pyramid.tif";
  options.pan = "300,100";
  options.zoom = 0.25;
  for (const int frame : {0, 77}) {
    int level = -1;
    EXPECT_EQ(wrong_pixels(options, sides, frame, {300, 100, 4}, &level), 0) << frame;
    EXPECT_EQ(level, 2);
  }
  options.pan = "0,0";
  options.zoom = 1;
  int level = -1;
  EXPECT_EQ(wrong_pixels(options, sides, 5, {0, 0, 1}, &level), 0);
  EXPECT_EQ(level, 0);
  // --zoom alone: centred on the picture.
  options.pan.clear();
  options.zoom = 0.5;
  EXPECT_EQ(wrong_pixels(options, sides, 0, {kWidth / 2.0, kHeight / 2.0, 2}, &level), 0);
  EXPECT_EQ(level, 1);
  fs::remove_all(dir);
}

TEST(PictureLevels, AFileWithFewerLevelsShowsItsLast) {
  const fs::path dir = scratch("picture-two-levels");
  const std::vector<Side> sides = halvings(2);
  write_pyramid(dir / "two.tif", sides);
  int level = -1;
  EXPECT_EQ(wrong_pixels(dir / "two.tif", sides, 0, &level), 0);
  EXPECT_EQ(level, 1);
  fs::remove_all(dir);
}

TEST(PictureLevels, LevelsThatDoNotHalveAreOneLine) {
  const fs::path dir = scratch("picture-bad-levels");
  write_pyramid(dir / "bad.tif", {{kWidth, kHeight}, {kWidth / 2, kHeight / 2}, {300, 40}});
  SceneOptions options;
  options.content = dir / "bad.tif";
  try {
    make_scene("picture", options);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              options.content.string() +
                  ": cannot read: MIP level 2 is 300x40, not half of level 1's 544x192");
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
