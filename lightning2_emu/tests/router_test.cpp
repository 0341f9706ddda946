#include "lightning2_emu/router.hpp"

#include <gtest/gtest.h>

#include <random>

#include "lightning2_emu/frame_builder.hpp"

namespace l2 {
namespace {

using testing::FrameBuilder;
using testing::pattern;

constexpr Rgb kBackground{10, 20, 30};
constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255};

// A mesh with displays 0 and 1 (16x4 and 8x2) and inputs 0..3.
struct Fixture {
  WorkerPool pool;
  Router router;
  explicit Fixture(int workers = 1)
      : pool(workers), router(Mesh(1, 1), {{0, 16, 4, 0}, {1, 8, 2, 0}}, pool, kBackground) {}
  RouteReport route(const std::vector<const RgbImage*>& inputs) {
    std::vector<InputFrame> frames;
    for (const RgbImage* image : inputs) {
      frames.push_back(image ? InputFrame::of(*image) : InputFrame{});
    }
    return router.route(frames);
  }
  const RgbImage& display(int id) { return router.display(router.index_of_display(id)).back(); }
};

StripErrorCounts errors(std::uint64_t check, std::uint64_t ext, std::uint64_t zero,
                        std::uint64_t trunc, std::uint64_t missing, std::uint64_t clips) {
  return {check, ext, zero, trunc, missing, clips};
}

// Row y of a display as colours, for readable comparisons.
std::vector<Rgb> row_of(const RgbImage& image, int y) {
  std::vector<Rgb> row;
  for (int x = 0; x < image.width(); ++x) row.push_back(image.at(x, y));
  return row;
}

TEST(Router, CopiesStripsToTheirDisplayRowAndColumn) {
  Fixture f;
  FrameBuilder in(32, 4);
  int x = in.copy(0, 0, 0, 3, 1, 5);  // display 0, row 1, columns 3..7
  x = in.skip(x, 0, 4);
  in.copy(x, 0, 1, 0, 0, 8);   // display 1, row 0, all of it
  in.copy(0, 2, 0, 0, 3, 16);  // display 0, row 3, whole row
  const RouteReport r = f.route({&in.image()});
  for (int k = 0; k < 5; ++k) EXPECT_EQ(f.display(0).at(3 + k, 1), pattern(0, 3 + k, 1));
  EXPECT_EQ(f.display(0).at(2, 1), kBackground);
  EXPECT_EQ(f.display(0).at(8, 1), kBackground);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(f.display(1).at(k, 0), pattern(1, k, 0));
  for (int k = 0; k < 16; ++k) EXPECT_EQ(f.display(0).at(k, 3), pattern(0, k, 3));
  EXPECT_EQ(row_of(f.display(0), 0), std::vector<Rgb>(16, kBackground));
  EXPECT_EQ(row_of(f.display(1), 1), std::vector<Rgb>(8, kBackground));

  ASSERT_EQ(r.inputs.size(), 4u);
  EXPECT_EQ(r.inputs[0].copy_strips, 3u);
  EXPECT_EQ(r.inputs[0].skip_strips, 1u);
  EXPECT_EQ(r.inputs[0].routed_strips, 3u);
  EXPECT_EQ(r.inputs[0].displays_fed, 0b11u);
  EXPECT_EQ(r.inputs[0].parities, 1u);
  EXPECT_EQ(r.inputs[0].errors, StripErrorCounts{});
  EXPECT_FALSE(r.inputs[1].present);
  ASSERT_EQ(r.displays.size(), 2u);
  EXPECT_EQ(r.displays[0].display, 0);
  EXPECT_EQ(r.displays[0].strips, 2u);
  EXPECT_EQ(r.displays[0].covered_pixels, 21u);
  EXPECT_EQ(r.displays[0].overdraw_pixels, 0u);
  EXPECT_EQ(r.displays[1].strips, 1u);
  EXPECT_EQ(r.displays[1].covered_pixels, 8u);
  EXPECT_DOUBLE_EQ(r.displays[1].coverage(), 0.5);
}

// Spec §3, row 1: a bad check drops the rest of the scanline; the next scanline is parsed.
TEST(Router, CheckErrorDropsTheRestOfTheScanline) {
  Fixture f;
  FrameBuilder in(40, 2);
  int x = in.copy_fill(0, 0, 0, 0, 0, 4, kRed);
  in.raw_header(x, 0, encode(StripHeader::copy(false, 0, 4, 0, 4)) ^ 1);  // check broken
  in.copy_fill(x + 2, 0, 0, 4, 0, 4, kGreen);  // a valid header where the strip would be
  in.copy_fill(0, 1, 0, 0, 1, 2, kBlue);
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(1, 0, 0, 0, 0, 0));
  EXPECT_EQ(r.inputs[0].copy_strips, 2u);
  EXPECT_EQ(f.display(0).at(3, 0), kRed);
  EXPECT_EQ(f.display(0).at(4, 0), kBackground);
  EXPECT_EQ(f.display(0).at(1, 1), kBlue);
}

// Row 2: an EXT whose extension word is black (kind 0, unsupported): rest of scanline dropped,
// counted.
TEST(Router, ExtDropsTheRestOfTheScanline) {
  Fixture f;
  FrameBuilder in(40, 3);
  in.header(0, 0, StripHeader{StripOp::Ext, false, 0, 0, 0, 4});
  in.copy_fill(6, 0, 0, 0, 0, 4, kRed);
  in.header(0, 2, StripHeader{StripOp::Ext, true, 3, 1, 2, 0});
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 2, 0, 0, 0, 0));
  EXPECT_EQ(r.inputs[0].copy_strips, 0u);
  EXPECT_EQ(row_of(f.display(0), 0), std::vector<Rgb>(16, kBackground));
}

// Spec §7, each rule once: COPY then KEY (transparent where the payload is the key colour);
// DEPTH writes only a strictly nearer pixel (equal depth: the earlier strip stays, far: never);
// no DEPTH covers a COPY pixel; a pixel reached only at the far plane shows the background.
TEST(Router, KeyAndDepthStripsCompositeAsSection7Says) {
  Fixture f;
  FrameBuilder in(64, 2);
  int x = in.copy_fill(0, 0, 0, 0, 0, 6, kRed);
  const int key = in.ext(x, 0, 0, 2, 0, 4, Extension::key_colour(0x00FF00));
  for (int k = 0; k < 4; ++k) in.image().set(key + k, 0, k % 2 ? kBlue : kGreen);
  x = in.depth(0, 1, 0, 0, 1, {kRed, kRed, kRed, kRed}, {5, 0xFFFFFF, 5, 0});
  x = in.depth(x, 1, 0, 0, 1, {kBlue, kBlue, kBlue, kBlue}, {5, 3, 6, 0});
  x = in.copy_fill(x, 1, 0, 4, 1, 2, kGreen);
  in.depth(x, 1, 0, 4, 1, {kBlue, kBlue, kBlue}, {0, 0, 0xFFFFFF});
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, StripErrorCounts{});
  EXPECT_EQ(r.inputs[0].copy_strips, 2u);
  EXPECT_EQ(r.inputs[0].key_strips, 1u);
  EXPECT_EQ(r.inputs[0].depth_strips, 3u);
  EXPECT_EQ(r.inputs[0].routed_strips, 6u);
  std::vector<Rgb> row0(16, kBackground), row1(16, kBackground);
  for (int k = 0; k < 6; ++k) row0[k] = k == 3 || k == 5 ? kBlue : kRed;
  row1[0] = kRed, row1[1] = kBlue, row1[2] = kRed, row1[3] = kRed;
  row1[4] = row1[5] = kGreen;  // row1[6]: only a far-plane DEPTH pixel
  EXPECT_EQ(row_of(f.display(0), 0), row0);
  EXPECT_EQ(row_of(f.display(0), 1), row1);
  EXPECT_EQ(row_of(f.display(0), 2), std::vector<Rgb>(16, kBackground));
  EXPECT_EQ(r.displays[0].strips, 6u);
  EXPECT_EQ(r.displays[0].covered_pixels, 12u);   // written: row 0 columns 0..5, row 1 0..5
  EXPECT_EQ(r.displays[0].overdraw_pixels, 10u);  // in two strips: 2..5, and 0..5 of row 1
  EXPECT_TRUE(f.router.composites(0));
  EXPECT_FALSE(f.router.composites(1));
}

// The next frame starts from the background at far depth: nothing of the last frame's
// compositing is left, in pixels or depths.
TEST(Router, CompositingStartsEveryFrameFromTheFarPlane) {
  Fixture f;
  FrameBuilder near(64, 1), far(64, 1);
  near.depth(0, 0, 0, 0, 0, {kRed, kRed}, {1, 1});
  far.depth(0, 0, 0, 0, 0, {kBlue, kGreen}, {0xFFFFFE, 0xFFFFFF});
  f.route({&near.image()});
  const RouteReport r = f.route({&far.image()});
  std::vector<Rgb> row(16, kBackground);
  row[0] = kBlue;
  EXPECT_EQ(row_of(f.display(0), 0), row);
  EXPECT_EQ(r.displays[0].covered_pixels, 1u);
}

// The one rank that does not fit (composite.hpp): depth FFFFFE from input 255 of a 64-row mesh
// is still nearer than the far plane, in a span long enough for the vector loop and its tail.
TEST(Router, DepthJustShortOfTheFarPlaneFromTheLastInputIsWritten) {
  WorkerPool pool(1);
  Router router(Mesh(64, 1), {{0, 40, 1, 0}}, pool, kBackground);
  FrameBuilder in(128, 1);
  const std::vector<std::uint32_t> depths(40, 0xFFFFFE);
  in.depth(0, 0, 0, 0, 0, std::vector<Rgb>(40, kGreen), depths);
  std::vector<InputFrame> frames(256);
  frames[255] = InputFrame::of(in.image());
  const RouteReport r = router.route(frames);
  EXPECT_EQ(row_of(router.display(0).back(), 0), std::vector<Rgb>(40, kGreen));
  EXPECT_EQ(r.displays[0].covered_pixels, 40u);
}

// §7's error rows the router counts: a KEY to a display the mesh does not have skips its payload
// and the scanline goes on; a DEPTH partly outside its display writes the pixels inside.
TEST(Router, KeyAndDepthCountMissingDisplaysAndClips) {
  Fixture f;
  FrameBuilder in(64, 1);
  int x = in.ext(0, 0, 5, 0, 0, 3, Extension::key_colour(0));
  in.image().fill_rect(x, 0, 3, 1, kRed);
  x = in.depth(x + 3, 0, 1, 6, 0, {kRed, kGreen, kBlue, kBlue}, {1, 2, 3, 4});
  in.copy_fill(x, 0, 1, 0, 0, 2, kBlue);
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 0, 0, 0, 1, 1));
  std::vector<Rgb> row(8, kBackground);
  row[0] = row[1] = kBlue;
  row[6] = kRed;
  row[7] = kGreen;
  EXPECT_EQ(row_of(f.display(1), 0), row);
  EXPECT_FALSE(f.router.composites(0));
  EXPECT_TRUE(f.router.composites(1));
}

// Inputs delivering at different refreshes composite as in bus order: of equal depths the lower
// input stays though written last, a higher input's COPY still covers a lower one's DEPTH, and a
// lower input's COPY shows through a higher input's transparent KEY pixels only.
TEST(Router, CompositingAcrossRefreshesIsInBusOrder) {
  Fixture f;
  FrameBuilder low(64, 2), high(64, 2);
  low.depth(0, 0, 0, 0, 0, {kRed, kRed, kRed}, {7, 7, 7});
  int x = high.depth(0, 0, 0, 0, 0, {kBlue, kBlue}, {7, 6});
  high.copy_fill(x, 0, 0, 2, 0, 1, kGreen);
  low.copy_fill(0, 1, 0, 0, 1, 4, kRed);
  const int key = high.ext(0, 1, 0, 0, 1, 4, Extension::key_colour(0x0000FF));
  for (int k = 0; k < 4; ++k) high.image().set(key + k, 1, k < 2 ? kBlue : kGreen);
  const std::vector<InputFrame> frames{InputFrame::of(low.image()), InputFrame::of(high.image())};
  f.router.scan(frames);
  const std::vector<std::uint8_t> second{0, 1}, first{1, 0};
  f.router.write(second);
  f.router.write(first);
  std::vector<DisplayFrameStats> stats;
  const std::vector<int> displays{0};
  f.router.finish(displays, stats);
  std::vector<Rgb> row0(16, kBackground), row1(16, kBackground);
  row0[0] = kRed, row0[1] = kBlue, row0[2] = kGreen;
  row1[0] = row1[1] = kRed, row1[2] = row1[3] = kGreen;
  EXPECT_EQ(row_of(f.display(0), 0), row0);
  EXPECT_EQ(row_of(f.display(0), 1), row1);
}

// A scanline that repeats the last one's headers but not its extension word is parsed: the
// KEY below has another key colour.
TEST(Router, AScanlineRepeatsOnlyWithTheSameExtensionWords) {
  Fixture f;
  FrameBuilder in(64, 2);
  for (int y = 0; y < 2; ++y) {
    in.copy_fill(0, y, 0, 0, y, 4, kRed);
    const int key = in.ext(6, y, 0, 0, y, 4, Extension::key_colour(y == 0 ? 0x00FF00 : 0x0000FF));
    for (int k = 0; k < 4; ++k) in.image().set(key + k, y, k % 2 ? kBlue : kGreen);
  }
  f.route({&in.image()});
  EXPECT_EQ(row_of(f.display(0), 0)[0], kRed);
  EXPECT_EQ(row_of(f.display(0), 0)[1], kBlue);
  EXPECT_EQ(row_of(f.display(0), 1)[0], kGreen);
  EXPECT_EQ(row_of(f.display(0), 1)[1], kRed);
}

// A predicted frame holds the extension words too: a KEY whose key colour changed under the same
// header is found, the frame parsed, and composited with the new key.
TEST(Router, APredictionHoldsTheExtensionWordsToo) {
  Fixture f;
  FrameBuilder a(64, 1), b(64, 1);
  for (FrameBuilder* in : {&a, &b}) {
    const int x = in->copy_fill(0, 0, 0, 0, 0, 4, kRed);
    const int key =
        in->ext(x, 0, 0, 0, 0, 4, Extension::key_colour(in == &a ? 0x00FF00 : 0x0000FF));
    for (int k = 0; k < 4; ++k) in->image().set(key + k, 0, k % 2 ? kBlue : kGreen);
  }
  f.route({&a.image()});
  f.route({&b.image()});
  EXPECT_EQ(f.router.predictions().predicted, 1u);
  EXPECT_EQ(f.router.predictions().mispredicted, 1u);
  std::vector<Rgb> row(16, kBackground);
  row[0] = row[2] = kGreen;
  row[1] = row[3] = kRed;
  EXPECT_EQ(row_of(f.display(0), 0), row);
}

// Row 3: COPY or SKIP of width 0: rest of scanline dropped, counted.
TEST(Router, ZeroWidthDropsTheRestOfTheScanline) {
  Fixture f;
  FrameBuilder in(40, 2);
  int x = in.copy_fill(0, 0, 0, 0, 0, 2, kRed);
  in.header(x, 0, StripHeader::copy(false, 0, 5, 0, 0));
  in.copy_fill(x + 2, 0, 0, 5, 0, 3, kGreen);
  in.header(0, 1, StripHeader::skip(false, 0));
  in.copy_fill(2, 1, 0, 0, 1, 3, kGreen);
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 0, 2, 0, 0, 0));
  EXPECT_EQ(r.inputs[0].copy_strips, 1u);
  EXPECT_EQ(r.inputs[0].skip_strips, 0u);
  EXPECT_EQ(f.display(0).at(1, 0), kRed);
  EXPECT_EQ(f.display(0).at(5, 0), kBackground);
  EXPECT_EQ(f.display(0).at(0, 1), kBackground);
}

// Row 4: a strip past the end of the scanline: the pixels that exist are routed.
TEST(Router, TruncatedStripRoutesThePixelsThatExist) {
  Fixture f;
  FrameBuilder in(10, 2);
  in.header(0, 0, StripHeader::copy(false, 0, 2, 0, 12));  // 8 pixels exist: columns 2..9
  in.image().fill_rect(2, 0, 8, 1, kRed);
  in.skip(0, 1, 6);
  in.header(8, 1, StripHeader::copy(false, 0, 0, 1, 3));  // header in the last two pixels
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 0, 0, 2, 0, 0));
  EXPECT_EQ(r.inputs[0].copy_strips, 2u);
  EXPECT_EQ(r.inputs[0].routed_strips, 1u);
  std::vector<Rgb> expected(16, kBackground);
  for (int k = 2; k < 10; ++k) expected[k] = kRed;
  EXPECT_EQ(row_of(f.display(0), 0), expected);
  EXPECT_EQ(row_of(f.display(0), 1), std::vector<Rgb>(16, kBackground));
  EXPECT_EQ(r.displays[0].covered_pixels, 8u);
}

// Row 5: a display the mesh lacks: its pixels are skipped and parsing goes on.
TEST(Router, MissingDisplaySkipsTheStripAndGoesOn) {
  Fixture f;
  FrameBuilder in(40, 1);
  int x = in.copy_fill(0, 0, 5, 0, 0, 4, kRed);  // display 5 is not configured
  x = in.copy_fill(x, 0, 63, 0, 0, 2, kRed);     // nor 63 (beyond the 1x1 mesh)
  in.copy_fill(x, 0, 0, 0, 0, 3, kGreen);
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 0, 0, 0, 2, 0));
  EXPECT_EQ(r.inputs[0].copy_strips, 3u);
  EXPECT_EQ(r.inputs[0].routed_strips, 1u);
  EXPECT_EQ(f.display(0).at(2, 0), kGreen);
  EXPECT_EQ(f.display(0).at(3, 0), kBackground);
}

// Row 6: a strip partly or wholly outside its display: only the pixels inside are written.
TEST(Router, ClipsStripsAtDisplayEdges) {
  Fixture f;
  FrameBuilder in(64, 3);
  int x = in.copy(0, 0, 1, 5, 1, 6);         // display 1 is 8 wide: columns 5..7 of 5..10
  x = in.copy_fill(x, 0, 1, 8, 0, 2, kRed);  // starts right of the display
  in.copy_fill(x, 0, 1, 0, 2, 2, kRed);      // row 2 of a 2-row display
  in.copy(0, 1, 1, 0, 0, 3);                 // after two clips on row 0, row 1 is parsed
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(0, 0, 0, 0, 0, 3));
  EXPECT_EQ(r.inputs[0].routed_strips, 2u);
  std::vector<Rgb> expected(8, kBackground);
  for (int k = 5; k < 8; ++k) expected[k] = pattern(1, k, 1);
  EXPECT_EQ(row_of(f.display(1), 1), expected);
  std::vector<Rgb> row0(8, kBackground);
  for (int k = 0; k < 3; ++k) row0[k] = pattern(1, k, 0);
  EXPECT_EQ(row_of(f.display(1), 0), row0);
  EXPECT_EQ(r.displays[1].covered_pixels, 6u);
}

TEST(Router, CountsEveryErrorOfAFrameExactly) {
  Fixture f;
  FrameBuilder in(32, 8);
  in.raw_header(0, 0, 0x000000000001);  // check error
  in.header(0, 1, StripHeader{StripOp::Ext, false, 0, 0, 0, 1});
  in.header(0, 2, StripHeader::copy(false, 0, 0, 0, 0));
  in.header(0, 3, StripHeader::copy(false, 0, 0, 0, 40));   // truncated and clipped
  in.header(0, 4, StripHeader::copy(false, 9, 0, 0, 3));    // missing
  in.header(5, 4, StripHeader::copy(false, 0, 15, 0, 3));   // clipped
  in.header(10, 4, StripHeader::copy(false, 0, 0, 0, 30));  // truncated and clipped
  in.raw_header(0, 5, 0xFFFFFFFFFFFF);                      // check error (white)
  const RouteReport r = f.route({&in.image()});
  EXPECT_EQ(r.inputs[0].errors, errors(2, 1, 1, 2, 1, 3));
  EXPECT_EQ(r.errors().total(), 10u);
}

// Spec §5: higher input wins; within one input, the later strip in scan order wins.
TEST(Router, OverlapPriorityFollowsThePixelBus) {
  Fixture f;
  FrameBuilder in0(32, 2), in1(32, 2), in3(32, 2);
  in0.copy_fill(0, 0, 0, 0, 0, 10, kRed);   // columns 0..9
  in1.copy_fill(0, 0, 0, 4, 0, 4, kGreen);  // 4..7 over input 0
  in3.copy_fill(0, 1, 0, 6, 0, 4, kBlue);   // 6..9 over both
  // Input 0 later in its own scan order: row 1 over its own row 0, under inputs 1 and 3.
  in0.copy_fill(0, 1, 0, 2, 0, 6, Rgb{1, 2, 3});  // 2..7
  const RouteReport r = f.route({&in0.image(), &in1.image(), nullptr, &in3.image()});
  const Rgb own{1, 2, 3};
  const std::vector<Rgb> expected = {
      kRed,  kRed,  own,         own,         kGreen,      kGreen,      kBlue,       kBlue,
      kBlue, kBlue, kBackground, kBackground, kBackground, kBackground, kBackground, kBackground};
  EXPECT_EQ(row_of(f.display(0), 0), expected);
  EXPECT_EQ(r.displays[0].strips, 4u);
  EXPECT_EQ(r.displays[0].covered_pixels, 10u);
  EXPECT_EQ(r.displays[0].overdraw_pixels, 8u);  // columns 2..9 each written twice or more
}

TEST(Router, SameScanlineLaterStripWins) {
  Fixture f;
  FrameBuilder in(40, 1);
  int x = in.copy_fill(0, 0, 0, 0, 0, 6, kRed);
  in.copy_fill(x, 0, 0, 3, 0, 6, kGreen);
  f.route({&in.image()});
  std::vector<Rgb> expected(16, kBackground);
  for (int k = 0; k < 3; ++k) expected[k] = kRed;
  for (int k = 3; k < 9; ++k) expected[k] = kGreen;
  EXPECT_EQ(row_of(f.display(0), 0), expected);
}

// Every frame starts from the background: what the last frame wrote does not linger.
TEST(Router, UnwrittenPixelsShowTheBackgroundEveryFrame) {
  Fixture f;
  FrameBuilder full(40, 4), part(40, 4);
  for (int y = 0; y < 4; ++y) full.copy_fill(0, y, 0, 0, y, 16, kRed);
  part.copy_fill(0, 2, 0, 4, 2, 4, kGreen);
  f.route({&full.image()});
  EXPECT_EQ(f.display(0), RgbImage(16, 4, kRed));
  const RouteReport r = f.route({&part.image()});
  RgbImage expected(16, 4, kBackground);
  expected.fill_rect(4, 2, 4, 1, kGreen);
  EXPECT_EQ(f.display(0), expected);
  EXPECT_EQ(f.display(1), RgbImage(8, 2, kBackground));
  EXPECT_EQ(r.displays[0].covered_pixels, 4u);
}

TEST(Router, ReadsRgbaRowsWithAnyStride) {
  Fixture f;
  // An RGBA frame stored bottom-up with padding: row 0 last in memory, negative stride.
  const int width = 12, height = 2, stride = width * 4 + 8;
  std::vector<std::uint8_t> memory(static_cast<std::size_t>(stride) * height, 0);
  auto row = [&](int y) { return memory.data() + (height - 1 - y) * stride; };
  write_header_pixels(encode(StripHeader::copy(true, 0, 1, 3, 4)), row(1), 4);
  for (int k = 0; k < 4; ++k) {
    std::uint8_t* p = row(1) + (2 + k) * 4;
    p[0] = static_cast<std::uint8_t>(k);
    p[1] = 7;
    p[2] = 9;
    p[3] = 0x55;
  }
  const InputFrame frame{row(0), -stride, width, height, 4};
  const RouteReport r = f.router.route(std::span(&frame, 1));
  EXPECT_EQ(r.inputs[0].routed_strips, 1u);
  EXPECT_EQ(r.inputs[0].parities, 2u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(f.display(0).at(1 + k, 3), (Rgb{static_cast<std::uint8_t>(k), 7, 9}));
  }
}

TEST(Router, RefusesFramesTheMeshCannotTake) {
  WorkerPool pool(1);
  Router router(Mesh(1, 1, {64, 32}), {{0, 16, 4, 0}}, pool);
  const RgbImage big(65, 10), ok(64, 32);
  std::vector<InputFrame> frames = {InputFrame::of(ok), InputFrame::of(big)};
  try {
    router.scan(frames);
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(), "input 1: input 1 is 65x10, larger than the board limit 64x32");
  }
  frames.assign(5, InputFrame::of(ok));
  EXPECT_THROW(router.scan(frames), MeshError);
  EXPECT_THROW(Router(Mesh(1, 1), {{8, 16, 4, 0}}, pool), MeshError);  // display beyond mesh
  EXPECT_THROW(Router(Mesh(1, 1), {{1, 16, 4, 0}, {1, 8, 8, 0}}, pool), MeshError);
}

// Tiles packed per spec §4 land exactly where they belong, whatever the worker count.
TEST(Router, PackedTilesRebuildTheDisplaysWithAnyWorkerCount) {
  const std::vector<DisplaySpec> displays = {{0, 200, 150, 0}, {3, 120, 90, 0}};
  std::vector<std::vector<testing::Tile>> tiles(3);
  int n = 0;
  for (const DisplaySpec& d : displays) {
    for (int y = 0; y < d.height; y += 30) {
      for (int x = 0; x < d.width; x += 40) {
        tiles[n++ % 3].push_back(
            {d.id, x, y, std::min(40, d.width - x), std::min(30, d.height - y)});
      }
    }
  }
  std::vector<RgbImage> frames(3, RgbImage(256, 256));
  std::vector<InputFrame> views;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(testing::pack_frame(tiles[i], i % 2 == 0, frames[i]));
    views.push_back(InputFrame::of(frames[i]));
  }
  RouteReport first;
  for (int workers : {1, 2, 3}) {
    WorkerPool pool(workers);
    Router router(Mesh(1, 1, {256, 256}), displays, pool);
    const RouteReport r = router.route(views);
    for (const DisplaySpec& d : displays) {
      EXPECT_EQ(router.display(router.index_of_display(d.id)).back(),
                testing::pattern_image(d.id, d.width, d.height))
          << "display " << d.id << " with " << workers << " workers";
    }
    EXPECT_EQ(r.displays[0].covered_pixels, 200u * 150u);
    EXPECT_EQ(r.displays[1].covered_pixels, 120u * 90u);
    EXPECT_EQ(r.displays[0].overdraw_pixels, 0u);
    EXPECT_EQ(r.errors().total(), 0u);
    if (workers == 1) first = r;
    EXPECT_EQ(r, first);
  }
}

}  // namespace
}  // namespace l2
