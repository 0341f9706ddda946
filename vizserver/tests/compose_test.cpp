#include "compose.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <vector>

namespace l2::viz {
namespace {

// A tile whose pixel (c, r) is (base + c, r, 7): every pixel tells where it came from.
std::vector<std::uint8_t> numbered(int w, int h, int base) {
  std::vector<std::uint8_t> px;
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      px.push_back(static_cast<std::uint8_t>(base + c));
      px.push_back(static_cast<std::uint8_t>(r));
      px.push_back(7);
    }
  }
  return px;
}

TEST(ComposeTile, InsideTileLandsPixelForPixelFromAStridedFramebuffer) {
  std::vector<RgbImage> displays{RgbImage(8, 6), RgbImage(4, 4)};
  // A 3x2 tile at column 2 of a 5-pixel-wide framebuffer: stride 15 bytes.
  const auto fb = numbered(5, 2, 0);
  StripErrorCounts counts;
  compose_tile(displays, TileHeader{0, 0, 4, 3, 3, 2}, fb.data() + 2 * 3, 15, counts);
  EXPECT_EQ(counts, StripErrorCounts{});
  EXPECT_EQ(displays[0].at(4, 3), (Rgb{2, 0, 7}));
  EXPECT_EQ(displays[0].at(6, 4), (Rgb{4, 1, 7}));
  EXPECT_EQ(displays[0].at(3, 3), (Rgb{}));
  EXPECT_EQ(displays[0].at(7, 3), (Rgb{}));
  EXPECT_EQ(displays[0].at(4, 5), (Rgb{}));
  EXPECT_EQ(displays[1], RgbImage(4, 4));
}

TEST(ComposeTile, RowsOutsideTheDisplayAreClippedAndCountedPerRow) {
  std::vector<RgbImage> displays{RgbImage(4, 4)};
  const auto px = numbered(3, 3, 10);
  StripErrorCounts counts;
  // Columns 2..4 on a 4-wide display (one column out), rows 2..4 (one row out).
  compose_tile(displays, TileHeader{0, 0, 2, 2, 3, 3}, px.data(), 9, counts);
  EXPECT_EQ(counts.clips, 3u);  // row 2 and 3 partly out, row 4 wholly out
  EXPECT_EQ(displays[0].at(2, 2), (Rgb{10, 0, 7}));
  EXPECT_EQ(displays[0].at(3, 3), (Rgb{11, 1, 7}));
  EXPECT_EQ(displays[0].at(1, 2), (Rgb{}));
}

TEST(ComposeTile, NegativeOffsetsKeepTheVisiblePart) {
  std::vector<RgbImage> displays{RgbImage(4, 4)};
  const auto px = numbered(3, 2, 20);
  StripErrorCounts counts;
  compose_tile(displays, TileHeader{0, 0, -2, -1, 3, 2}, px.data(), 9, counts);
  EXPECT_EQ(counts.clips, 2u);
  EXPECT_EQ(displays[0].at(0, 0), (Rgb{22, 1, 7}));
  EXPECT_EQ(displays[0].at(1, 0), (Rgb{}));
}

TEST(ComposeTile, HostileOffsetsAndMissingDisplaysWriteNothing) {
  std::vector<RgbImage> displays{RgbImage(4, 4)};
  const auto px = numbered(2, 2, 0);
  StripErrorCounts counts;
  compose_tile(displays, TileHeader{0, 0, INT_MAX, INT_MAX, 2, 2}, px.data(), 6, counts);
  compose_tile(displays, TileHeader{0, 0, INT_MIN, 0, 2, 2}, px.data(), 6, counts);
  compose_tile(displays, TileHeader{0, 5, 0, 0, 2, 2}, px.data(), 6, counts);
  EXPECT_EQ(counts.clips, 4u);
  EXPECT_EQ(counts.missing_display, 2u);
  EXPECT_EQ(displays[0], RgbImage(4, 4));
}

// Spec §7 on one 4x1 display, tiles in bus order, values worked out by hand.
TEST(ComposeTile, KeyAndDepthCompositeAsTheEmulatorDoes) {
  std::vector<RgbImage> displays{RgbImage(4, 1)};
  std::vector<DepthPlane> depths(1, DepthPlane(4, 0xFFFFFF));
  StripErrorCounts counts;
  const auto depth_tile = [&](std::vector<std::uint8_t> colour_then_depth) {
    compose_tile(displays, depths, TileHeader{0, 0, 0, 0, 4, 1, TileKind::Depth, 0},
                 colour_then_depth.data(), 24, counts);
  };
  // Layer A: depths 5, 5, far, 9.
  depth_tile({1, 0, 0, 2, 0, 0, 3,    0,    0,    4, 0, 0,  // colour
              0, 0, 5, 0, 0, 5, 0xFF, 0xFF, 0xFF, 0, 0, 9});
  // Layer B: depths 4 (nearer), 5 (a tie: A stays), 6 (nearer than far), 9 (a tie).
  depth_tile({10, 0, 0, 20, 0, 0, 30, 0, 0, 40, 0, 0, 0, 0, 4, 0, 0, 5, 0, 0, 6, 0, 0, 9});
  EXPECT_EQ(displays[0].at(0, 0), (Rgb{10, 0, 0}));
  EXPECT_EQ(displays[0].at(1, 0), (Rgb{2, 0, 0}));
  EXPECT_EQ(displays[0].at(2, 0), (Rgb{30, 0, 0}));
  EXPECT_EQ(displays[0].at(3, 0), (Rgb{4, 0, 0}));
  EXPECT_EQ(depths[0], (DepthPlane{4, 5, 6, 9}));
  // A KEY over columns 1..3, key colour 000102 transparent at column 2: opaque, depth 0.
  const std::vector<std::uint8_t> key{7, 7, 7, 0, 1, 2, 8, 8, 8};
  compose_tile(displays, depths, TileHeader{0, 0, 1, 0, 3, 1, TileKind::Key, 0x000102}, key.data(),
               9, counts);
  EXPECT_EQ(displays[0].at(1, 0), (Rgb{7, 7, 7}));
  EXPECT_EQ(displays[0].at(2, 0), (Rgb{30, 0, 0}));
  EXPECT_EQ(depths[0], (DepthPlane{4, 0, 6, 0}));
  // Depth 0 everywhere: nearer than 4 and 6, so columns 0 and 2 change; the KEY pixels hold
  // depth 0 already and stay (no DEPTH strip covers an opaque overlay).
  depth_tile({50, 0, 0, 60, 0, 0, 70, 0, 0, 80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(displays[0].at(0, 0), (Rgb{50, 0, 0}));
  EXPECT_EQ(displays[0].at(1, 0), (Rgb{7, 7, 7}));
  EXPECT_EQ(displays[0].at(2, 0), (Rgb{70, 0, 0}));
  EXPECT_EQ(displays[0].at(3, 0), (Rgb{8, 8, 8}));
  EXPECT_EQ(counts, StripErrorCounts{});
}

}  // namespace
}  // namespace l2::viz
