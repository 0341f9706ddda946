// Sparse DEPTH rows (tilelayout/sparse_depth.hpp): DEPTH strips over part of a tile's row and a
// SKIP over the rest composite as the dense row does, the pixels they leave out show the
// background, and frames whose spans move from frame to frame route right. Expected rows are
// worked out by hand from spec §7.
#include <gtest/gtest.h>

#include <vector>

#include "lightning2_emu/frame_builder.hpp"
#include "lightning2_emu/router.hpp"

namespace l2::sparse_rows_test {
namespace {

using testing::FrameBuilder;

constexpr Rgb kBackground{10, 20, 30};
constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kBlack{};
constexpr std::uint32_t kFar = 0xFFFFFF;

// One 16x4 display; a DEPTH tile of 16 pixels takes 4 + 32 columns of a 38-column frame.
struct Fixture {
  WorkerPool pool;
  Router router;
  explicit Fixture(int workers)
      : pool(workers), router(Mesh(1, 1), {{0, 16, 4, 0}}, pool, kBackground) {}
  RouteReport route(const std::vector<const RgbImage*>& inputs) {
    std::vector<InputFrame> frames;
    for (const RgbImage* image : inputs) frames.push_back(InputFrame::of(*image));
    return router.route(frames);
  }
  std::vector<Rgb> row(int y) {
    const RgbImage& d = router.display(0).back();
    std::vector<Rgb> out;
    for (int x = 0; x < d.width(); ++x) out.push_back(d.at(x, y));
    return out;
  }
};

// Row y of a dense tile: 16 pixels of `colour`, at `depth` on [from, to) and far elsewhere.
void dense_row(FrameBuilder& in, int y, Rgb colour, std::uint32_t depth, int from, int to) {
  std::vector<std::uint32_t> depths(16, kFar);
  for (int x = from; x < to; ++x) depths[static_cast<std::size_t>(x)] = depth;
  in.depth(0, y, 0, 0, y, std::vector<Rgb>(16, colour), depths);
}

// The same row sparse: one DEPTH strip over [from, to), a SKIP over the rest of the 36 columns.
void sparse_row(FrameBuilder& in, int y, Rgb colour, std::uint32_t depth, int from, int to) {
  const int w = to - from;
  const int x = in.depth(0, y, 0, from, y, std::vector<Rgb>(static_cast<std::size_t>(w), colour),
                         std::vector<std::uint32_t>(static_cast<std::size_t>(w), depth));
  in.skip(x, y, 36 - x - 2);
}

TEST(SparseRows, CompositeAsTheirDenseRows) {
  for (int workers : {1, 2}) {
    // Input 0 nearer (4) on 2..5, input 1 at 5 on 0..7; on every row.
    FrameBuilder dense0(38, 4), dense1(38, 4), sparse0(38, 4), sparse1(38, 4);
    for (int y = 0; y < 4; ++y) {
      dense_row(dense0, y, kRed, 4, 2, 6);
      dense_row(dense1, y, kBlue, 5, 0, 8);
      sparse_row(sparse0, y, kRed, 4, 2, 6);
      sparse_row(sparse1, y, kBlue, 5, 0, 8);
    }
    std::vector<Rgb> want(16, kBackground);
    for (int x = 0; x < 8; ++x) want[static_cast<std::size_t>(x)] = x >= 2 && x < 6 ? kRed : kBlue;
    Fixture f(workers);
    const RouteReport dense = f.route({&dense0.image(), &dense1.image()});
    for (int y = 0; y < 4; ++y) EXPECT_EQ(f.row(y), want) << workers << " dense row " << y;
    const RouteReport sparse = f.route({&sparse0.image(), &sparse1.image()});
    for (int y = 0; y < 4; ++y) EXPECT_EQ(f.row(y), want) << workers << " sparse row " << y;
    EXPECT_EQ(dense.displays[0].covered_pixels, 32u);
    EXPECT_EQ(sparse.displays[0].covered_pixels, 32u);
    EXPECT_EQ(sparse.inputs[0].errors, StripErrorCounts{});
    EXPECT_EQ(sparse.inputs[0].depth_strips, 4u);
  }
}

TEST(SparseRows, WhatTheyLeaveOutShowsTheBackgroundAfterAFullFrame) {
  Fixture f(1);
  FrameBuilder full(38, 4), sparse(38, 4);
  for (int y = 0; y < 4; ++y) dense_row(full, y, kRed, 1, 0, 16);
  // Row 1 draws 5..6 only; the other rows send nothing but a SKIP.
  for (int y = 0; y < 4; ++y) {
    if (y == 1) {
      sparse_row(sparse, y, kGreen, 1, 5, 7);
    } else {
      sparse.skip(0, y, 34);
    }
  }
  f.route({&full.image()});
  EXPECT_EQ(f.row(3), std::vector<Rgb>(16, kRed));
  const RouteReport r = f.route({&sparse.image()});
  std::vector<Rgb> row1(16, kBackground);
  row1[5] = row1[6] = kGreen;
  EXPECT_EQ(f.row(0), std::vector<Rgb>(16, kBackground));
  EXPECT_EQ(f.row(1), row1);
  EXPECT_EQ(f.row(3), std::vector<Rgb>(16, kBackground));
  EXPECT_EQ(r.displays[0].covered_pixels, 2u);
  // And the full frame again: every pixel composited anew.
  f.route({&full.image()});
  EXPECT_EQ(f.row(1), std::vector<Rgb>(16, kRed));
}

TEST(SparseRows, SpansThatMoveFromFrameToFrameRouteRight) {
  // The router predicts a frame from the last (router.hpp); moved spans put other headers where
  // it looks, and the frame is parsed. Black drawn at a near depth is drawn, not background.
  Fixture f(2);
  FrameBuilder a(38, 4), b(38, 4);
  for (int y = 0; y < 4; ++y) {
    sparse_row(a, y, kBlack, 3, y, y + 3);
    sparse_row(b, y, kGreen, 3, 10 - y, 12);
  }
  for (int frame = 0; frame < 3; ++frame) {
    for (const FrameBuilder* in : {&a, &b, &a}) {
      f.route({&in->image()});
      for (int y = 0; y < 4; ++y) {
        std::vector<Rgb> want(16, kBackground);
        const bool is_a = in == &a;
        const int from = is_a ? y : 10 - y, to = is_a ? y + 3 : 12;
        for (int x = from; x < to; ++x) want[static_cast<std::size_t>(x)] = is_a ? kBlack : kGreen;
        EXPECT_EQ(f.row(y), want) << "frame " << frame << " row " << y;
      }
    }
  }
}

}  // namespace
}  // namespace l2::sparse_rows_test
