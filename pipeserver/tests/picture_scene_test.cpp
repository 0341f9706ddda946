// The picture scene on a small wall: the routed displays equal the picture's pixels as the
// view samples them (worked out here from the picture's formula), zoomed out, half way and at
// 1:1; and the view's path keeps the canvas covered.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "image/png_io.hpp"
#include "pipeserver/picture_view.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

Rgb pattern(int x, int y) {
  return {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
          static_cast<std::uint8_t>(x / 7 + y / 5)};
}

constexpr int kWidth = 600, kHeight = 400;

fs::path write_pattern(const fs::path& path) {
  RgbImage picture(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) picture.set(x, y, pattern(x, y));
  write_png(path, picture);
  return path;
}

long sampled(double centre, double scale, int size, int x) {
  return static_cast<long>(std::floor(centre + (x + 0.5 - size / 2.0) * scale));
}

TEST(PictureView, FrameZeroShowsAWholeSideCentred) {
  const SourceView v = picture_view(0, kWidth, kHeight, {136, 48});
  EXPECT_DOUBLE_EQ(v.scale_x, 600.0 / 136);  // the width: 600/136 < 400/48
  EXPECT_DOUBLE_EQ(v.centre_x, 300);
  EXPECT_DOUBLE_EQ(v.centre_y, 200);
  // Half a period on, one picture pixel per canvas pixel.
  EXPECT_NEAR(picture_view(kPictureZoomPeriod / 2, kWidth, kHeight, {136, 48}).scale_x, 1, 1e-12);
  // A picture smaller than the canvas is magnified to cover it, and stays so.
  EXPECT_DOUBLE_EQ(picture_view(77, 68, 12, {136, 48}).scale_x, 0.25);
}

TEST(PictureView, TheCanvasStaysCoveredAllAlongThePath) {
  const Canvas canvas{136, 48};
  for (int k = 0; k < 3000; k += 7) {
    const SourceView v = picture_view(k, kWidth, kHeight, canvas);
    EXPECT_GE(sampled(v.centre_x, v.scale_x, canvas.width, 0), 0) << k;
    EXPECT_LT(sampled(v.centre_x, v.scale_x, canvas.width, canvas.width - 1), kWidth) << k;
    EXPECT_GE(sampled(v.centre_y, v.scale_y, canvas.height, 0), 0) << k;
    EXPECT_LT(sampled(v.centre_y, v.scale_y, canvas.height, canvas.height - 1), kHeight) << k;
  }
}

// A 600x400 source on a 136x48 canvas (wider than the source's 3:2): fit shows all of it (the
// height decides, bars left and right), fill covers the canvas (the width decides), stretch
// scales each axis apart so the source's corners are the canvas's.
TEST(SourceFit, EachFitLaysTheSourceAsItsNameSays) {
  const Canvas canvas{136, 48};
  const SourceView fit = movie_view(kWidth, kHeight, canvas, SourceFit::Fit);
  EXPECT_DOUBLE_EQ(fit.scale_x, 400.0 / 48);
  EXPECT_DOUBLE_EQ(fit.scale_y, 400.0 / 48);
  EXPECT_LT(sampled(fit.centre_x, fit.scale_x, canvas.width, 0), 0);  // a bar on the left
  const SourceView fill = movie_view(kWidth, kHeight, canvas, SourceFit::Fill);
  EXPECT_DOUBLE_EQ(fill.scale_x, 600.0 / 136);
  EXPECT_DOUBLE_EQ(fill.scale_y, 600.0 / 136);
  EXPECT_GT(sampled(fill.centre_y, fill.scale_y, canvas.height, 0), 0);  // cropped at the top
  const SourceView stretch = movie_view(kWidth, kHeight, canvas, SourceFit::Stretch);
  EXPECT_DOUBLE_EQ(stretch.scale_x, 600.0 / 136);
  EXPECT_DOUBLE_EQ(stretch.scale_y, 400.0 / 48);
  // Nearest sampling at pixel centres: the first and last canvas pixels sample within the
  // first and last scale's worth of source pixels on each axis.
  EXPECT_EQ(sampled(stretch.centre_x, stretch.scale_x, canvas.width, 0), 2);  // 0.5 * 4.41
  EXPECT_EQ(sampled(stretch.centre_x, stretch.scale_x, canvas.width, 135), 597);
  EXPECT_EQ(sampled(stretch.centre_y, stretch.scale_y, canvas.height, 0), 4);  // 0.5 * 8.33
  EXPECT_EQ(sampled(stretch.centre_y, stretch.scale_y, canvas.height, 47), 395);
  // The picture's default is fill, as before --fit; its zoom still reaches 1:1 on both axes.
  EXPECT_DOUBLE_EQ(picture_view(0, kWidth, kHeight, canvas).scale_x, fill.scale_x);
  const SourceView near =
      picture_view(kPictureZoomPeriod / 2, kWidth, kHeight, canvas, SourceFit::Stretch);
  EXPECT_NEAR(near.scale_x, 1, 1e-12);
  EXPECT_NEAR(near.scale_y, 1, 1e-12);
  EXPECT_EQ(parse_source_fit("stretch"), SourceFit::Stretch);
  EXPECT_EQ(parse_source_fit("cover"), std::nullopt);
}

// What a desktop's coordinator sends for a tile (sampled_source) is exactly what nearest
// sampling reads for it: the bounding box of every pixel's source index, clipped to the source,
// for every fit and rectangles inside, across and past a window's edges.
TEST(SourceFit, TheSampledSourceIsExactlyWhatTheSamplingReads) {
  const Canvas canvas{136, 48};
  for (const SourceFit f :
       {SourceFit::Fit, SourceFit::Fill, SourceFit::Stretch, SourceFit::OneToOne}) {
    const SourceView v = movie_view(kWidth, kHeight, canvas, f);
    for (const Rect r : {Rect{0, 0, 136, 48}, Rect{3, 5, 1, 1}, Rect{0, 0, 7, 48},
                         Rect{120, 40, 16, 8}, Rect{50, 10, 30, 20}}) {
      long x0 = kWidth, y0 = kHeight, x1 = -1, y1 = -1;
      for (int y = r.y; y < r.bottom(); ++y) {
        for (int x = r.x; x < r.right(); ++x) {
          const long sx = sampled(v.centre_x, v.scale_x, canvas.width, x);
          const long sy = sampled(v.centre_y, v.scale_y, canvas.height, y);
          if (sx < 0 || sx >= kWidth || sy < 0 || sy >= kHeight) continue;
          x0 = std::min(x0, sx), y0 = std::min(y0, sy);
          x1 = std::max(x1, sx), y1 = std::max(y1, sy);
        }
      }
      const Rect want = x1 < 0 ? Rect{}
                               : Rect{static_cast<int>(x0), static_cast<int>(y0),
                                      static_cast<int>(x1 - x0 + 1), static_cast<int>(y1 - y0 + 1)};
      EXPECT_EQ(sampled_source(v, kWidth, kHeight, canvas, r), want)
          << static_cast<int>(f) << " " << r.x << "," << r.y << " " << r.w << "x" << r.h;
    }
  }
  // 1:1 on a window wider than the source: its right part samples nothing.
  EXPECT_TRUE(
      sampled_source(movie_view(10, 10, canvas, SourceFit::OneToOne), 10, 10, canvas, {20, 0, 5, 5})
          .empty());
}

TEST(PictureScene, RoutedDisplaysArePicturePixels) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("picture-scene-{}", getpid());
  SceneOptions options;
  options.content = write_pattern(dir / "pattern.png");
  auto scene = make_scene("picture", options);
  const TileLayout layout = test::small_layout(3, 40, 20, 120, 120);
  const Canvas canvas = canvas_of(layout.wall);
  for (const int frame : {0, kPictureZoomPeriod / 4, kPictureZoomPeriod / 2}) {
    std::vector<RgbImage> frames;
    for (int s = 0; s < 3; ++s) frames.push_back(Pipeserver(layout, s).render_frame(frame, *scene));
    const auto r = test::reassemble(layout.wall, frames);
    EXPECT_EQ(r.errors.total(), 0u);
    const SourceView v = picture_view(frame, kWidth, kHeight, canvas);
    for (const Display& d : layout.wall.displays) {
      const RgbImage& shown = r.displays[static_cast<std::size_t>(d.id)];
      const Rect on = d.on_canvas();
      long wrong = 0;
      for (int y = 0; y < shown.height(); ++y) {
        const long sy = sampled(v.centre_y, v.scale_y, canvas.height, on.y + y);
        for (int x = 0; x < shown.width(); ++x) {
          const long sx = sampled(v.centre_x, v.scale_x, canvas.width, on.x + x);
          wrong += !(shown.at(x, y) == pattern(static_cast<int>(sx), static_cast<int>(sy)));
        }
      }
      EXPECT_EQ(wrong, 0) << "frame " << frame << " display " << d.id;
    }
  }
  fs::remove_all(dir);
}

TEST(PictureScene, ADamagedPictureIsOneLine) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("picture-bad-{}", getpid());
  fs::create_directories(dir);
  SceneOptions options;
  options.content = dir / "text.png";
  std::ofstream(options.content) << "not a picture\n";
  try {
    make_scene("picture", options);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), options.content.string() + ": cannot read: Not a PNG file");
  }
  options.content.clear();
  EXPECT_THROW(make_scene("movie", options), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
