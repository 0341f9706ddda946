// A packed stereo wall (docs/wall-file.md, "Stereo walls"): each display's left (top) half shows
// the left eye's picture of the whole display squeezed into it and the other half the right
// eye's. Reassembled through the pipeservers, each half equals the passive wall's eye picture
// of the same canvas rectangle rendered at the half's size, byte for byte, and is that picture
// at full size with each pair of columns (rows) averaged, but for edges; a square at a known
// depth lies apart between the halves by the parallax the eye separation gives, worked out here
// from the geometry (stereo_square.hpp): e·f·(1/c − 1/d) canvas pixels, half of it in a
// side-by-side half's squeezed pixels, all of it in a top-bottom half's.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer.hpp"
#include "stereo_square.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_scenes.hpp"

namespace l2::packed_test {
namespace {

using namespace stereo_square;
using test::crop;

// One 320x240 display, tiles of 70x50 dealt to two pipeservers. "passive": twins, one per eye.
TileLayout layout_of(const std::string& mode) {
  return square_wall(mode, 70, 50, 400, 320);
}

// The halves of a packed display: left (top) then right (bottom).
std::pair<RgbImage, RgbImage> halves(const RgbImage& d, bool side) {
  const Rect first =
      side ? Rect{0, 0, d.width() / 2, d.height()} : Rect{0, 0, d.width(), d.height() / 2};
  const Rect second = side ? Rect{d.width() / 2, 0, d.width() / 2, d.height()}
                           : Rect{0, d.height() / 2, d.width(), d.height() / 2};
  return {crop(d, first), crop(d, second)};
}

// The right half's square centre less the left half's (x), and the same in y.
std::pair<double, double> measured_shift(const std::string& mode, float z) {
  auto scene = square_at(z);
  const auto [first, second] =
      halves(reassembled(layout_of(mode), *scene, 0)[0], mode == "side-by-side");
  const Lit left = lit(first), right = lit(second);
  // A square some 30 squeezed pixels a side or more, whole in both halves.
  EXPECT_GT(left.count, 1000);
  EXPECT_GT(right.count, 1000);
  return {right.x - left.x, right.y - left.y};
}

TEST(PackedStereo, SideBySideHalvesDifferByHalfTheParallax) {
  const double want = expected_parallax(kCameraDistance - 1) / 2;  // squeezed: half the pixels
  EXPECT_NEAR(want, -10.99, 0.01);  // the formula's figure, for a reader checking it by hand
  const auto [dx, dy] = measured_shift("side-by-side", 1.0f);
  EXPECT_NEAR(dx, want, 0.5);
  EXPECT_NEAR(dy, 0.0, 0.1);
  EXPECT_NEAR(measured_shift("side-by-side", -1.0f).first,
              expected_parallax(kCameraDistance + 1) / 2, 0.5);
  EXPECT_NEAR(measured_shift("side-by-side", 0.0f).first, 0.0, 0.5);
}

TEST(PackedStereo, TopBottomHalvesDifferByTheWholeParallax) {
  const auto [dx, dy] = measured_shift("top-bottom", 1.0f);
  EXPECT_NEAR(dx, expected_parallax(kCameraDistance - 1), 0.5);  // columns are not squeezed
  EXPECT_NEAR(dy, 0.0, 0.1);
  EXPECT_NEAR(measured_shift("top-bottom", -1.0f).first, expected_parallax(kCameraDistance + 1),
              0.5);
}

// The passive wall's eye `eye` of the whole display, rendered at the size of a half.
RgbImage passive_eye_at(const TileLayout& passive, Scene& scene, Eye eye, int w, int h) {
  return render_canvas_rect(canvas_of(passive.wall), {0, 0, w, h}, scene, 0,
                            {eye, passive.wall.stereo}, {0, 0, kWidth, kHeight});
}

// Pixels of `squeezed` further than 48 levels (in some channel) from the mean of the two pixels
// of `full` it stands for: columns 2i and 2i+1 side by side, rows top-bottom.
long far_from_averaged(const RgbImage& squeezed, const RgbImage& full, bool side) {
  long far = 0;
  for (int y = 0; y < squeezed.height(); ++y) {
    for (int x = 0; x < squeezed.width(); ++x) {
      const Rgb a = full.at(side ? 2 * x : x, side ? y : 2 * y);
      const Rgb b = full.at(side ? 2 * x + 1 : x, side ? y : 2 * y + 1);
      const Rgb s = squeezed.at(x, y);
      const auto off = [](int v, int p, int q) { return std::abs(2 * v - p - q) > 96; };
      far += off(s.r, a.r, b.r) || off(s.g, a.g, b.g) || off(s.b, a.b, b.b);
    }
  }
  return far;
}

// The mesh scene, lit and coloured: each half is the passive wall's eye picture of the display
// rendered at the half's size, byte for byte, and that eye's full-size picture (the passive
// twins reassembled) with each column (row) pair averaged, but for a few edge pixels.
TEST(PackedStereo, EachHalfIsThePassiveWallsEyeAtTheHalfsSize) {
  const TileLayout passive = layout_of("passive");
  auto scene = make_scene("mesh", test::small_options());
  const std::vector<RgbImage> twins = reassembled(passive, *scene, 0);
  for (const std::string mode : {"side-by-side", "top-bottom"}) {
    SCOPED_TRACE(mode);
    const bool side = mode == "side-by-side";
    const auto [first, second] = halves(reassembled(layout_of(mode), *scene, 0)[0], side);
    EXPECT_TRUE(first == passive_eye_at(passive, *scene, Eye::Left, first.width(), first.height()));
    EXPECT_TRUE(second ==
                passive_eye_at(passive, *scene, Eye::Right, second.width(), second.height()));
    EXPECT_FALSE(first == second);
    const long area = static_cast<long>(first.width()) * first.height();
    EXPECT_LT(far_from_averaged(first, twins[0], side), area / 20);
    EXPECT_LT(far_from_averaged(second, twins[1], side), area / 20);
  }
}

// The example walls reassemble to their references on every scene of geometry.
TEST(PackedStereo, TheExampleWallsReassembleExactly) {
  for (const char* name : {"stereo-side-by-side-2x1.toml", "stereo-top-bottom-2x1.toml"}) {
    const TileLayout layout =
        plan_layout(load_wall(std::filesystem::path(L2_SOURCE_DIR) / "examples/walls" / name));
    auto scene = make_scene("mesh", test::small_options());
    SCOPED_TRACE(name);
    EXPECT_EQ(reassembled(layout, *scene, 3).size(), 2u);
  }
}

}  // namespace
}  // namespace l2::packed_test
