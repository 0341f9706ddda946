// `stereo` and `eye` of a wall file (docs/wall-file.md, "Stereo walls"): what is read, what a
// passive wall's twins must be, and what is refused, each in one line naming file, line, field.
#include <gtest/gtest.h>

#include <tuple>

#include "tilelayout/plan_report.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::stereo_test {
namespace {

// Two projectors per eye, each pair on one half of a 200x80 canvas. Line numbers matter.
const std::string kStereoPassive =
    "[stereo]\n"                                                      // 1
    "mode = \"passive\"\n"                                            // 2
    "eye_separation = 0.2\n"                                          // 3
    "convergence = 3\n"                                               // 4
    "[[display]]\n"                                                   // 5
    "width = 100\nheight = 80\nx = 0\ny = 0\neye = \"left\"\n"        // 6-10
    "[[display]]\n"                                                   // 11
    "width = 100\nheight = 80\nx = 100\ny = 0\neye = \"left\"\n"      // 12-16
    "[[display]]\n"                                                   // 17
    "width = 100\nheight = 80\nx = 0\ny = 0\neye = \"right\"\n"       // 18-22
    "[[display]]\n"                                                   // 23
    "width = 100\nheight = 80\nx = 100\ny = 0\neye = \"right\"\n"     // 24-28
    "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 40\n"  // 29-32
    "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 400\n";

const std::string kStereoGrid =
    "stereo = \"passive\"\n"
    "[display_grid]\ncolumns = 2\nrows = 1\nwidth = 100\nheight = 80\nmonitors = [\"a\", \"b\"]\n"
    "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 40\n"
    "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 400\n";

std::string stereo_replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string stereo_error(const std::string& text) {
  try {
    parse_wall(text, "walls/s.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WallStereo, MonoWallsHaveNoEyes) {
  const Wall w =
      parse_wall(stereo_replace(kStereoGrid, "stereo = \"passive\"\n", ""), "walls/s.toml");
  EXPECT_EQ(w.stereo.mode, StereoMode::Mono);
  ASSERT_EQ(w.displays.size(), 2u);
  EXPECT_EQ(w.displays[0].eye, Eye::None);
  EXPECT_TRUE(eye_pairs(w).empty());
}

TEST(WallStereo, ReadsAPassiveWallOfTwins) {
  const Wall w = parse_wall(kStereoPassive, "walls/s.toml");
  EXPECT_EQ(w.stereo.mode, StereoMode::Passive);
  EXPECT_DOUBLE_EQ(w.stereo.eye_separation, 0.2);
  EXPECT_DOUBLE_EQ(w.stereo.convergence, 3.0);
  EXPECT_EQ(w.stereo.line, 2);
  ASSERT_EQ(w.displays.size(), 4u);
  EXPECT_EQ(w.displays[0].eye, Eye::Left);
  EXPECT_EQ(w.displays[3].eye, Eye::Right);
  const auto pairs = eye_pairs(w);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].left, 0);
  EXPECT_EQ(pairs[0].right, 2);
  EXPECT_EQ(pairs[1].left, 1);
  EXPECT_EQ(pairs[1].right, 3);
  EXPECT_EQ(w.canvas_width, 200);
}

TEST(WallStereo, DefaultsWithoutTheSection) {
  const Wall w = parse_wall(kStereoGrid, "walls/s.toml");
  EXPECT_EQ(w.stereo.mode, StereoMode::Passive);
  EXPECT_DOUBLE_EQ(w.stereo.eye_separation, 0.1);
  EXPECT_DOUBLE_EQ(w.stereo.convergence, 0.0);
}

TEST(WallStereo, APassiveGridIsTwinnedForTheRightEye) {
  const Wall w = parse_wall(kStereoGrid, "walls/s.toml");
  ASSERT_EQ(w.displays.size(), 4u);
  EXPECT_EQ(w.displays[1].eye, Eye::Left);
  EXPECT_EQ(w.displays[1].monitor, "b");
  EXPECT_EQ(w.displays[3].id, 3);
  EXPECT_EQ(w.displays[3].eye, Eye::Right);
  EXPECT_EQ(w.displays[3].on_canvas(), (Rect{100, 0, 100, 80}));
  EXPECT_EQ(w.displays[3].monitor, "");
  EXPECT_EQ(w.canvas_width, 200);
}

TEST(WallStereo, EveryTwinGetsDisplayTilesOfItsOwn) {
  // The eye is part of the tile: each logical tile reaches both twins, so there are twice the
  // display tiles of the mono wall, half on each eye's displays.
  const TileLayout layout = plan_layout(parse_wall(kStereoPassive, "walls/s.toml"));
  std::vector<int> per_display(4, 0);
  for (const auto& p : layout.pipeservers)
    for (const auto& t : p.tiles) ++per_display[static_cast<std::size_t>(t.tile.display)];
  EXPECT_EQ(per_display, (std::vector<int>{4, 4, 4, 4}));
  const std::string plan = format_plan(layout);
  EXPECT_NE(plan.find("display 2: 100x80 at canvas 0,0, swap group 0, right eye: 100.0% covered"),
            std::string::npos)
      << plan;
}

TEST(WallStereo, RefusesBadStereoValues) {
  EXPECT_EQ(
      stereo_error(stereo_replace(kStereoPassive, "mode = \"passive\"", "mode = \"anaglyph\"")),
      "walls/s.toml:2: stereo.mode: must be \"passive\", \"active\", \"side-by-side\" or "
      "\"top-bottom\", got \"anaglyph\"");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoGrid, "stereo = \"passive\"", "stereo = 3")),
            "walls/s.toml:1: stereo: must be \"passive\", \"active\", \"side-by-side\" or "
            "\"top-bottom\" or a [stereo] section, got an integer");
  EXPECT_EQ(
      stereo_error(stereo_replace(kStereoPassive, "eye_separation = 0.2", "eye_separation = -1")),
      "walls/s.toml:3: stereo.eye_separation: must be a number from 0 up to below 2, got -1");
  EXPECT_EQ(
      stereo_error(stereo_replace(kStereoPassive, "convergence = 3", "convergence = \"far\"")),
      "walls/s.toml:4: stereo.convergence: must be a number, got a string");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "convergence = 3", "toe_in = 3"))
                .rfind("walls/s.toml:4: stereo.toe_in: unknown key", 0),
            0u);
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "mode = \"passive\"\n", "")),
            "walls/s.toml:1: stereo.mode: missing (required): \"passive\", \"active\", "
            "\"side-by-side\" or \"top-bottom\"");
}

TEST(WallStereo, PassiveDisplaysNeedTwinsInOneSwapGroup) {
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "x = 100\ny = 0\neye = \"right\"",
                                        "x = 100\ny = 0")),
            "walls/s.toml:23: display 3: eye missing: every display of a passive stereo wall "
            "shows \"left\" or \"right\"");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "x = 100\ny = 0\neye = \"right\"",
                                        "x = 100\ny = 0\neye = \"left\"")),
            "walls/s.toml:11: display 1: display 1 (eye = \"left\", 100x80 at 100,0): another "
            "display of the same eye covers the same rectangle");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "x = 100\ny = 0\neye = \"right\"",
                                        "x = 100\ny = 1\neye = \"right\"")),
            "walls/s.toml:11: display 1: display 1 (eye = \"left\", 100x80 at 100,0): no display "
            "of the other eye covers the same canvas rectangle (each eye's display needs a twin "
            "of the other eye at the same x, y and size)");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "x = 100\ny = 0\neye = \"right\"",
                                        "x = 100\ny = 0\neye = \"right\"\nswap_group = 1")),
            "walls/s.toml:11: display 1: swap_group 0, but its twin display 3 has 1: both eyes "
            "of a frame swap together");
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "eye = \"left\"", "eye = \"both\"")),
            "walls/s.toml:10: display[0].eye: must be one of left, right, got \"both\"");
}

TEST(WallStereo, EyesOnlyOnAPassiveWall) {
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive,
                                        "[stereo]\nmode = \"passive\"\neye_separation = 0.2\n"
                                        "convergence = 3\n",
                                        "")),
            "walls/s.toml:1: display 0: eye is only for a wall with stereo = \"passive\"");
}

// An active wall: the grid's two displays, no eyes, each showing both (frame_eye).
std::string active_grid() {
  return stereo_replace(kStereoGrid, "\"passive\"", "\"active\"");
}

TEST(WallStereo, AnActiveWallsDisplaysShowBothEyesInTurn) {
  const Wall w = parse_wall(active_grid(), "walls/s.toml");
  EXPECT_EQ(w.stereo.mode, StereoMode::Active);
  ASSERT_EQ(w.displays.size(), 2u);  // not twinned
  EXPECT_EQ(w.displays[1].eye, Eye::None);
  EXPECT_TRUE(eye_pairs(w).empty());
  const std::string plan = format_plan(plan_layout(w));
  EXPECT_NE(plan.find("display 1: 100x80 at canvas 100,0, swap group 0, both eyes in turn (active "
                      "stereo): 100.0% covered"),
            std::string::npos)
      << plan;
  // Eye frames: 2k the left eye of frame k, 2k+1 its right.
  for (const auto& [frame, app, eye] :
       {std::tuple{0, 0, Eye::Left}, {1, 0, Eye::Right}, {6, 3, Eye::Left}, {7, 3, Eye::Right}}) {
    EXPECT_EQ(frame_eye(w.stereo, frame).frame, app) << frame;
    EXPECT_EQ(frame_eye(w.stereo, frame).eye, eye) << frame;
  }
  StereoSpec passive;
  passive.mode = StereoMode::Passive;
  EXPECT_EQ(frame_eye(passive, 7).frame, 7);
  EXPECT_EQ(frame_eye(passive, 7).eye, Eye::None);
}

TEST(WallStereo, AnActiveWallHasNoEyesAndOneSwapGroup) {
  EXPECT_EQ(stereo_error(stereo_replace(kStereoPassive, "mode = \"passive\"", "mode = \"active\"")),
            "walls/s.toml:5: display 0: eye is only for a wall with stereo = \"passive\"");
  const std::string two_groups =
      "stereo = \"active\"\n"                                                    // 1
      "[[display]]\nwidth = 100\nheight = 80\nx = 0\ny = 0\n"                    // 2-6
      "[[display]]\nwidth = 100\nheight = 80\nx = 100\ny = 0\nswap_group = 1\n"  // 7-12
      "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 40\n"
      "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 400\n";
  EXPECT_EQ(stereo_error(two_groups),
            "walls/s.toml:7: display 1: swap_group 1, but display 0 has 0: every display of an "
            "active stereo wall shows the same eye in each refresh");
}

TEST(WallStereo, RefusesWhatStereoCannotDoYet) {
  // A passive wall's displays with eyes, made packed: packing has no eyes on its displays.
  EXPECT_EQ(
      stereo_error(stereo_replace(kStereoPassive, "mode = \"passive\"", "mode = \"side-by-side\"")),
      "walls/s.toml:5: display 0: eye is only for a wall with stereo = \"passive\"");
  EXPECT_EQ(stereo_error(active_grid() + "[depth]\nlayers = 2\n"),
            "walls/s.toml:17: depth: stereo walls do not support depth compositing yet");
  EXPECT_EQ(stereo_error(kStereoGrid + "[depth]\nlayers = 2\n"),
            "walls/s.toml:17: depth: stereo walls do not support depth compositing yet");
  // Projectors overlapping by 10 columns, each with its twin: blend would have edges to ramp.
  EXPECT_EQ(
      stereo_error(stereo_replace(stereo_replace(kStereoGrid, "stereo = \"passive\"\n",
                                                 "stereo = \"passive\"\nblend = \"linear\"\n"),
                                  "height = 80\n", "height = 80\nmullion_x = -10\n")),
      "walls/s.toml:2: blend: stereo walls do not support blending yet");
}

}  // namespace
}  // namespace l2::stereo_test
