// The verifier on the test wall's real scan-out (tilelayout's test_frame), corrupted the ways a
// routing goes wrong: each case's counts and report lines follow from the wall's geometry
// (verify_test_wall.hpp), worked out by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "tilelayout/test_pattern.hpp"
#include "verify/check_picture.hpp"
#include "verify/check_report.hpp"
#include "verify/routing_check.hpp"
#include "verify/verify_run.hpp"
#include "verify_test_wall.hpp"

namespace l2 {
namespace {

using verify_test::header_at;
using verify_test::scanned_out;
using verify_test::set_header;
using verify_test::test_layout;

std::string hex(const StripHeader& h) {
  return fmt::format("{:012x}", encode(h));
}

std::vector<std::string> report_of(const TileLayout& layout, const std::vector<RgbImage>& frames) {
  return check_report(check_routing(layout, frames));
}

TEST(RoutingCheck, CorrectScanOutIsRight) {
  const TileLayout layout = test_layout();
  const RoutingCheck check = check_routing(layout, scanned_out(layout));
  EXPECT_TRUE(check.clean());
  EXPECT_EQ(check_report(check),
            (std::vector<std::string>{
                "display 0 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "display 1 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "routing right: every planned pixel in place on 2 displays"}));
}

TEST(RoutingCheck, ForgottenInput) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  frames.pop_back();  // pipeserver 1's frame: tiles 1 and 3, the right halves
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_FALSE(check.clean());
  EXPECT_EQ(check_report(check),
            (std::vector<std::string>{
                "display 0 (64x32) wrong: 2048 planned pixels: 1024 right, 1024 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "display 1 (64x32) wrong: 2048 planned pixels: 1024 right, 1024 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "frames given for 1 of the wall's 2 pipeservers: input 1 sent nothing",
                "routing wrong: 2 of 2 displays wrong, 0 inputs with refused strips"}));
  for (int x : {0, 31, 32, 63}) {
    EXPECT_EQ(check.displays[0].kinds[5 * 64 + x], x < 32 ? PixelKind::Right : PixelKind::Missing);
  }
}

TEST(RoutingCheck, SwappedHeaders) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Scanline 5 of pipeserver 0: tile 0's header (display 0) and tile 2's (display 1) swapped.
  const StripHeader to_display_0 = header_at(frames[0], 2, 5);
  const StripHeader to_display_1 = header_at(frames[0], 36, 5);
  set_header(frames[0], 2, 5, to_display_1);
  set_header(frames[0], 36, 5, to_display_0);
  EXPECT_EQ(report_of(layout, frames),
            (std::vector<std::string>{
                "display 0 (64x32) wrong: 2048 planned pixels: 2016 right, 0 missing, 32 "
                "misplaced; 0 written twice, 0 behind mullions",
                "display 1 (64x32) wrong: 2048 planned pixels: 2016 right, 0 missing, 32 "
                "misplaced; 0 written twice, 0 behind mullions",
                "input 0: 2 strips not as planned for pipeserver 0, first at row 5 column 2: "
                "found d=1 x=0 y=5 w=32, planned d=0 x=0 y=5 w=32",
                "misplaced runs: 2",
                "  input 0 row 5 from column 36 (header " + hex(to_display_0) +
                    " COPY f=0 d=0 x=0 y=5 w=32): 32x1 pixels landed on display 0 at 0,5, "
                    "belong on display 1 at 0,5",
                "  input 0 row 5 from column 2 (header " + hex(to_display_1) +
                    " COPY f=0 d=1 x=0 y=5 w=32): 32x1 pixels landed on display 1 at 0,5, "
                    "belong on display 0 at 0,5",
                "routing wrong: 2 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned"}));
}

TEST(RoutingCheck, HeaderOffByOneRow) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Every header of tile 1 (pipeserver 1, display 0 at 32,0) one display row too low: row 0 is
  // missing, rows 1-31 show the row above, the last scanline falls below the display.
  for (int y = 0; y < 32; ++y)
    set_header(frames[1], 2, y, StripHeader::copy(false, 0, 32, y + 1, 32));
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_EQ(check_report(check),
            (std::vector<std::string>{
                "display 0 (64x32) wrong: 2048 planned pixels: 1024 right, 32 missing, 992 "
                "misplaced; 0 written twice, 32 behind mullions",
                "display 1 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "input 1: 32 strips not as planned for pipeserver 1, first at row 0 column 2: "
                "found d=0 x=32 y=1 w=32, planned d=0 x=32 y=0 w=32",
                "misplaced runs: 1",
                "  input 1 rows 0-30 from column 2 (header " +
                    hex(StripHeader::copy(false, 0, 32, 1, 32)) +
                    " COPY f=0 d=0 x=32 y=1 w=32): 32x31 pixels landed on display 0 at 32,1, "
                    "belong on display 0 at 32,0",
                "routing wrong: 1 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned"}));
  ASSERT_EQ(check.mullion_runs.size(), 1u);
  EXPECT_EQ(check.mullion_runs[0].start, (DisplayPoint{0, 32, 32}));
  EXPECT_EQ(check.mullion_runs[0].width, 32);
}

TEST(RoutingCheck, TileDrawnIntoWrongDisplay) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Tile 2 (pipeserver 0, display 1 at 0,0) sent to display 0: over tile 0, which it follows
  // on the scanline, so it wins there.
  for (int y = 0; y < 32; ++y) set_header(frames[0], 36, y, StripHeader::copy(false, 0, 0, y, 32));
  EXPECT_EQ(report_of(layout, frames),
            (std::vector<std::string>{
                "display 0 (64x32) wrong: 2048 planned pixels: 1024 right, 0 missing, 1024 "
                "misplaced; 1024 written twice, 0 behind mullions",
                "display 1 (64x32) wrong: 2048 planned pixels: 1024 right, 1024 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "input 0: 32 strips not as planned for pipeserver 0, first at row 0 column 36: "
                "found d=0 x=0 y=0 w=32, planned d=1 x=0 y=0 w=32",
                "misplaced runs: 1",
                "  input 0 rows 0-31 from column 36 (header " +
                    hex(StripHeader::copy(false, 0, 0, 0, 32)) +
                    " COPY f=0 d=0 x=0 y=0 w=32): 32x32 pixels landed on display 0 at 0,0, "
                    "belong on display 1 at 0,0",
                "routing wrong: 2 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned"}));
}

TEST(RoutingCheck, MullionOverlap) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Tile 1 (display 0 at 32,0, the right edge) shifted 8 columns right: its last 8 columns
  // fall into the mullion, its first 8 display columns stay empty.
  for (int y = 0; y < 32; ++y) set_header(frames[1], 2, y, StripHeader::copy(false, 0, 40, y, 32));
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_EQ(check_report(check),
            (std::vector<std::string>{
                "display 0 (64x32) wrong: 2048 planned pixels: 1024 right, 256 missing, 768 "
                "misplaced; 0 written twice, 256 behind mullions",
                "display 1 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "input 1: 32 strips not as planned for pipeserver 1, first at row 0 column 2: "
                "found d=0 x=40 y=0 w=32, planned d=0 x=32 y=0 w=32",
                "misplaced runs: 1",
                "  input 1 rows 0-31 from column 2 (header " +
                    hex(StripHeader::copy(false, 0, 40, 0, 32)) +
                    " COPY f=0 d=0 x=40 y=0 w=32): 24x32 pixels landed on display 0 at 40,0, "
                    "belong on display 0 at 32,0",
                "routing wrong: 1 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned"}));
  ASSERT_EQ(check.mullion_runs.size(), 32u);
  EXPECT_EQ(check.mullion_runs[7].start, (DisplayPoint{0, 64, 7}));
  EXPECT_EQ(check.mullion_runs[7].width, 8);
}

TEST(RoutingCheck, OverlappingTilesFromTwoInputs) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Tile 3 (pipeserver 1, display 1 at 32,0) drawn over tile 2 (pipeserver 0, display 1 at
  // 0,0): the later input on the bus wins, so tile 2's pixels are written twice and lost.
  for (int y = 0; y < 32; ++y) set_header(frames[1], 36, y, StripHeader::copy(false, 1, 0, y, 32));
  EXPECT_EQ(report_of(layout, frames),
            (std::vector<std::string>{
                "display 0 (64x32) right: 2048 planned pixels: 2048 right, 0 missing, 0 "
                "misplaced; 0 written twice, 0 behind mullions",
                "display 1 (64x32) wrong: 2048 planned pixels: 0 right, 1024 missing, 1024 "
                "misplaced; 1024 written twice, 0 behind mullions",
                "input 1: 32 strips not as planned for pipeserver 1, first at row 0 column 36: "
                "found d=1 x=0 y=0 w=32, planned d=1 x=32 y=0 w=32",
                "misplaced runs: 1",
                "  input 1 rows 0-31 from column 36 (header " +
                    hex(StripHeader::copy(false, 1, 0, 0, 32)) +
                    " COPY f=0 d=1 x=0 y=0 w=32): 32x32 pixels landed on display 1 at 0,0, "
                    "belong on display 1 at 32,0",
                "routing wrong: 1 of 2 displays wrong, 0 inputs with refused strips, 1 not as "
                "planned"}));
}

TEST(RoutingCheck, RefusedStripsAreNamedPerInput) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  frames[1].set(0, 3, {0, 0, 0});  // scanline 3's first header: check bits no longer match
  frames[1].set(1, 3, {0, 0, 1});
  set_header(frames[0], 36, 4, StripHeader::copy(false, 9, 0, 4, 32));  // no display 9
  const RoutingCheck check = check_routing(layout, frames);
  // The pixels the refused header's strip should have written are missing (marked so in the
  // picture), and with them the rest of its scanline: tile 3's row 3 on display 1.
  EXPECT_EQ(check.displays[0].kinds[3 * 64 + 40], PixelKind::Missing);
  EXPECT_EQ(check.displays[1].kinds[3 * 64 + 40], PixelKind::Missing);
  EXPECT_EQ(check.displays[0].kinds[4 * 64 + 40], PixelKind::Right);
  const std::vector<std::string> lines = check_report(check);
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines[2], "input 0: 32 pixels sent to displays the wall does not have");
  EXPECT_EQ(lines[3],
            "input 0: 1 strip not as planned for pipeserver 0, first at row 4 column 36: found "
            "d=9 x=0 y=4 w=32, planned d=1 x=0 y=4 w=32");
  // The refused header is named by its place; the rest of its scanline is lost with it.
  EXPECT_EQ(lines[4], "input 1: 1 check-bit errors, refused at row 3 column 0 (check-bit error)");
  EXPECT_EQ(lines[5],
            "input 1: 2 strips not as planned for pipeserver 1, first at row 3 column 2: found "
            "nothing, planned d=0 x=32 y=3 w=32");
  EXPECT_EQ(lines.back(),
            "routing wrong: 2 of 2 displays wrong, 2 inputs with refused strips, 2 not as planned");
}

TEST(RoutingCheck, CrossedCablesAreNamedThoughEveryPixelIsRight) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  std::swap(frames[0], frames[1]);
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_TRUE(check.displays[0].clean());
  EXPECT_TRUE(check.displays[1].clean());
  EXPECT_FALSE(check.clean());
  EXPECT_EQ(check.inputs[0].carries, 1);
  EXPECT_EQ(check.inputs[1].carries, 0);
  const std::vector<std::string> lines = check_report(check);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[2],
            "input 0 carries pipeserver 1's frame, not its own: a crossed cable (on a Lightning-2 "
            "READY goes to the wrong pipeserver, and the bus order changes where strips overlap)");
  EXPECT_EQ(lines[3].substr(0, 40), "input 1 carries pipeserver 0's frame, no");
  EXPECT_EQ(lines[4],
            "routing wrong: 0 of 2 displays wrong, 0 inputs with refused strips, 2 not as planned");
}

// The same wall with its tiles dealt otherwise (pipeserver 0 both of display 0's, pipeserver 1
// both of display 1's): every pixel lands right, but neither frame is the plan's.
TEST(RoutingCheck, FramesOfAnotherPlanOfTheSameWall) {
  const TileLayout layout = test_layout();
  std::string other_toml = verify_test::kWallToml;
  const std::string tiles = "[[0, 0, 32, 32], [32, 0, 32, 32], [80, 0, 32, 32], [112, 0, 32, 32]]";
  other_toml.replace(other_toml.find(tiles), tiles.size(),
                     "[[0, 0, 32, 32], [80, 0, 32, 32], [32, 0, 32, 32], [112, 0, 32, 32]]");
  const TileLayout other = plan_layout(parse_wall(other_toml, ""));
  const RoutingCheck check = check_routing(layout, scanned_out(other));
  EXPECT_TRUE(check.displays[0].clean() && check.displays[1].clean());
  EXPECT_FALSE(check.clean());
  const std::vector<std::string> lines = check_report(check);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[2],
            "input 0: 32 strips not as planned for pipeserver 0, first at row 0 column 36: found "
            "d=0 x=32 y=0 w=32, planned d=1 x=0 y=0 w=32");
  EXPECT_EQ(lines[3],
            "input 1: 32 strips not as planned for pipeserver 1, first at row 0 column 2: found "
            "d=1 x=0 y=0 w=32, planned d=0 x=32 y=0 w=32");
}

TEST(RoutingCheck, AFrameOfAnotherSizeIsNamed) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  RgbImage wider(96, 64);
  for (int y = 0; y < 64; ++y)
    std::copy(frames[1].row(y).begin(), frames[1].row(y).end(), wider.row(y).begin());
  frames[1] = std::move(wider);
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_FALSE(check.clean());
  const std::vector<std::string> lines = check_report(check);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2],
            "input 1: frame 96x64, but pipeserver 1's framebuffer is 80x64 (a frame of another "
            "wall?)");
  EXPECT_EQ(lines[3],
            "routing wrong: 0 of 2 displays wrong, 0 inputs with refused strips, 1 not as planned");
}

TEST(RoutingCheck, FrameParityMustAgreeAcrossInputs) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  frames[1] = test_frame(layout.pipeservers[1], true);  // the next application frame's parity
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_EQ(check.inputs[0].parity, 0);
  EXPECT_EQ(check.inputs[1].parity, 1);
  EXPECT_TRUE(check.parity_differs);
  EXPECT_FALSE(check.clean());
  const std::vector<std::string> lines = check_report(check);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2],
            "frame parity differs between inputs: f=0 on input 0; f=1 on input 1 (spec §6: the "
            "frames routed together carry one)");
  EXPECT_EQ(lines[3],
            "routing wrong: 0 of 2 displays wrong, 0 inputs with refused strips, frame parity "
            "differs");
}

TEST(RoutingCheck, AFrameOfBothParitiesIsTorn) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  set_header(frames[0], 2, 5, StripHeader::copy(true, 0, 0, 5, 32));  // one row of the next frame
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_EQ(check.inputs[0].parity, kMixedParity);
  EXPECT_FALSE(check.parity_differs);  // input 0 has no one parity to differ by
  const std::vector<std::string> lines = check_report(check);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2],
            "input 0: rows of both frame parities, a torn frame (spec §6: a frame has one)");
  EXPECT_EQ(lines[3], "routing wrong: 0 of 2 displays wrong, 0 inputs with refused strips, 1 torn");
}

TEST(RoutingCheck, ReportListsTheFirstRunsAndCountsTheRest) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  // Swapped on every other scanline: 16 x 2 runs that do not join (the rows between are right).
  for (int y = 0; y < 32; y += 2) {
    const StripHeader a = header_at(frames[0], 2, y), b = header_at(frames[0], 36, y);
    set_header(frames[0], 2, y, b);
    set_header(frames[0], 36, y, a);
  }
  const std::vector<std::string> lines = check_report(check_routing(layout, frames), 3);
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[3], "misplaced runs: 32");
  EXPECT_EQ(lines[7], "  ... and 29 more");
}

TEST(RoutingCheck, RoutedPixelsAreJudgedNotTheFrames) {
  const TileLayout layout = test_layout();
  const std::vector<RgbImage> frames = scanned_out(layout);
  std::vector<RgbImage> shown = route_on_wall(layout.wall, frames, 1);
  shown[1].set(10, 20, test_pattern(1, 11, 20));  // a router that copied one pixel wrong
  const std::vector<const RgbImage*> routed{&shown[0], &shown[1]};
  const RoutingCheck check = check_routing(layout, frames, routed);
  EXPECT_EQ(check.displays[1].misplaced, 1);
  ASSERT_EQ(check.misplaced.size(), 1u);
  EXPECT_EQ(describe_run(check.misplaced[0]),
            "input 0 row 20 from column 46 (header " + hex(StripHeader::copy(false, 1, 0, 20, 32)) +
                " COPY f=0 d=1 x=0 y=20 w=32): 1x1 pixels landed on display 1 at 10,20, belong "
                "on display 1 at 11,20");
}

// A correct routing of every example wall, through the emulator's router, verifies clean.
TEST(RoutingCheck, ExampleWallsVerifyClean) {
  int walls = 0;
  for (const auto& entry : std::filesystem::directory_iterator(L2_WALLS_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    const Wall wall = load_wall(entry.path());
    // Walls of several meshes are checked mesh by mesh (tilelayout's several-mesh tests).
    if (wall.mesh_count > 1) continue;
    ++walls;
    const TileLayout layout = plan_layout(wall);
    const std::vector<RgbImage> frames = scanned_out(layout);
    const std::vector<RgbImage> shown = route_on_wall(layout.wall, frames, 2);
    std::vector<const RgbImage*> routed;
    for (const RgbImage& s : shown) routed.push_back(&s);
    const RoutingCheck check = check_routing(layout, frames, routed);
    EXPECT_TRUE(check.clean()) << entry.path() << ": " << check_report(check).back();
    for (const DisplayCheck& d : check.displays) {
      EXPECT_EQ(d.right, d.planned) << entry.path() << " display " << d.display;
      EXPECT_GT(d.planned, 0) << entry.path() << " display " << d.display;
    }
  }
  EXPECT_GE(walls, 5);
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

// The picture of the mullion case: the shifted tile's wrong pixels in their kinds' colours,
// its last 8 columns in the margin right of the display, the rest dimmed.
TEST(CheckPicture, MarksEveryKindAndTheMargin) {
  const TileLayout layout = test_layout();
  std::vector<RgbImage> frames = scanned_out(layout);
  for (int y = 0; y < 32; ++y) {
    set_header(frames[1], 2, y, StripHeader::copy(false, 0, 40, y, 32));
  }
  const RoutingCheck check = check_routing(layout, frames);
  const std::vector<RgbImage> shown = route_on_wall(layout.wall, frames, 1);
  const RgbImage picture = check_picture(check, 0, shown[0]);
  ASSERT_EQ(check_margin(check.displays[0]), 8);
  EXPECT_EQ(picture.at(33, 4), kMissingColour);
  EXPECT_EQ(picture.at(40, 4), kMisplacedColour);
  EXPECT_EQ(picture.at(63, 31), kMisplacedColour);
  EXPECT_EQ(picture.at(64, 4), kMullionColour);
  EXPECT_EQ(picture.at(71, 31), kMullionColour);
  EXPECT_EQ(picture.at(64, 32), kMarginColour);  // below: nothing fell there
  // The misplaced run (40..63 x 0..31) framed 6 pixels out: over right and margin pixels, not
  // over the missing ones (32..39) nor the cyan ones that fell behind the mullion.
  EXPECT_EQ(picture.at(10, 37), kMarginColour);   // left of the frame
  EXPECT_EQ(picture.at(40, 37), kRunMarker);      // its bottom edge, in the margin
  EXPECT_EQ(picture.at(34, 10), kMissingColour);  // its left edge, over a missing pixel
  EXPECT_EQ(picture.at(69, 10), kMullionColour);  // its right edge, over a mullion pixel
  const Rgb c = test_pattern(0, 5, 6);
  EXPECT_EQ(picture.at(5, 6),
            (Rgb{static_cast<std::uint8_t>(c.r / 4), static_cast<std::uint8_t>(c.g / 4),
                 static_cast<std::uint8_t>(c.b / 4)}));
  EXPECT_GT(picture.height(), 32 + 8);  // the legend below
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

// Frames from elsewhere can hold anything: random bytes, and valid headers with random fields
// (displays the wall lacks, rows below it, strips past its edges). The check never reads or
// writes out of bounds (the ASan run), and its counts agree with its pixel kinds.
TEST(RoutingCheck, RandomHeadersAreCountedNotTrusted) {
  const TileLayout layout = test_layout();
  std::mt19937 rng(22);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (int round = 0; round < 40; ++round) {
    std::vector<RgbImage> frames = scanned_out(layout);
    for (RgbImage& f : frames) {
      for (int k = 0; k < 20; ++k) {
        const int y = uni(0, f.height() - 1), x = uni(2, f.width() - 1);
        if (round % 2 == 0) {
          f.set(x, y,
                {static_cast<std::uint8_t>(uni(0, 255)), static_cast<std::uint8_t>(uni(0, 255)),
                 static_cast<std::uint8_t>(uni(0, 255))});
        } else {
          set_header(f, x, y,
                     StripHeader::copy(uni(0, 1) == 1, uni(0, 63), uni(0, 4095), uni(0, 4095),
                                       uni(1, 4095)));
        }
      }
    }
    const RoutingCheck check = check_routing(layout, frames);
    for (const DisplayCheck& d : check.displays) {
      long long right = 0, missing = 0, misplaced = 0;
      for (PixelKind k : d.kinds) {
        right += k == PixelKind::Right || k == PixelKind::Twice;
        missing += k == PixelKind::Missing;
        misplaced += k == PixelKind::Misplaced;
      }
      EXPECT_EQ(d.right, right);
      EXPECT_EQ(d.missing, missing);
      EXPECT_EQ(d.misplaced, misplaced);
      EXPECT_LE(d.right + d.missing + d.misplaced, 64 * 32);
    }
    long long in_runs = 0;
    for (const MisplacedRun& r : check.misplaced)
      in_runs += static_cast<long long>(r.width) * r.rows;
    EXPECT_EQ(in_runs, check.displays[0].misplaced + check.displays[1].misplaced);
    check_report(check);  // formats whatever it found
  }
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

// The verifier composites KEY and DEPTH strips itself when it judges from the frames alone.
TEST(RoutingCheck, DepthLayersOutOfBusOrderAreMisplaced) {
  const TileLayout layout =
      plan_layout(load_wall(std::filesystem::path(L2_WALLS_DIR) / "sort-last-512x384.toml"));
  std::vector<RgbImage> frames = verify_test::scanned_out(layout);
  EXPECT_TRUE(check_routing(layout, frames).clean());
  // Layers 0 and 1 exchanged on the bus: where layer 0 wins by a tie with layer 1, layer 1 now
  // comes first and keeps its wrong colour (test_pattern.hpp).
  std::swap(frames[0], frames[1]);
  const RoutingCheck swapped = check_routing(layout, frames);
  EXPECT_FALSE(swapped.clean());
  EXPECT_GT(swapped.displays[0].misplaced, 0);
  EXPECT_EQ(swapped.displays[0].missing, 0);
  EXPECT_EQ(swapped.displays[0].written_twice, 0);  // DEPTH covers by design
}

TEST(RoutingCheck, AnOverlayWithoutWhatItCoversLeavesItsTransparentPixelsMissing) {
  const TileLayout layout =
      plan_layout(load_wall(std::filesystem::path(L2_WALLS_DIR) / "hybrid-2x1.toml"));
  std::vector<RgbImage> frames = verify_test::scanned_out(layout);
  EXPECT_TRUE(check_routing(layout, frames).clean());
  // Layer 0 and 1 frames black (idle): on display 0 only the overlay's opaque pixels arrive,
  // half of its 160x100 (4x4 blocks in a checkerboard; 160 and 100 are multiples of 8 and 4).
  for (int s = 0; s < 4; ++s) frames[s] = RgbImage(frames[s].width(), frames[s].height());
  const RoutingCheck c = check_routing(layout, frames);
  EXPECT_EQ(c.displays[0].right, 160 * 100 / 2);
  EXPECT_EQ(c.displays[0].missing, 400 * 300 - 160 * 100 / 2);
  EXPECT_EQ(c.displays[1].right, 0);
}

}  // namespace
}  // namespace l2
