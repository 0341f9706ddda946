// A passive stereo wall run live (examples/walls/stereo-passive-2x1.toml: two projectors per eye,
// each left-eye projector with a right-eye twin on its canvas rectangle), on both paths: every
// display shows, byte for byte, what the pipeserver program renders alone as that display's
// reference (its own eye's camera), the two eyes differ, and the summary says the swap-lock
// check proved both eyes of every frame shown together in every refresh. An active wall the
// same, each display showing a frame's left eye and then its right in consecutive refreshes; and
// packed walls (side-by-side, top-bottom), each display showing both eyes in its two halves.
#include <gtest/gtest.h>

#include "active_stereo_summary.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// The pixels of `a` that differ from `b`'s.
long pixels_differing(const RgbImage& a, const RgbImage& b) {
  long differ = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) differ += !(a.at(x, y) == b.at(x, y));
  return differ;
}

// Each of `displays` displays of frame `k` the run kept, on both paths, byte for byte as the
// pipeserver program renders it alone as that display's reference.
void expect_as_references(const WallRun& run, const fs::path& wall, int k, int displays) {
  const fs::path references = run.out().parent_path() / fmt::format("references-{}", k);
  ChildProcess reference({PIPESERVER_EXE, "--wall", wall.string(), "--scene", "mesh", "--frame",
                          std::to_string(k), "--reference", references.string()});
  const auto ended = reference.wait_for(120s);
  ASSERT_TRUE(ended && ended->ok()) << (ended ? ended->describe() : "did not end");
  const fs::path shown = run.out() / fmt::format("frame-{}", k);
  for (int d = 0; d < displays; ++d) {
    const RgbImage want = read_png(references / fmt::format("display-{}.png", d));
    EXPECT_TRUE(read_png(shown / fmt::format("display-{}.png", d)) == want)
        << "frame " << k << ", display " << d;
    EXPECT_TRUE(read_png(shown / fmt::format("display-{}-vizserver.png", d)) == want)
        << "frame " << k << ", display " << d;
  }
}

TEST(LiveRunStereo, PassiveTwinsShowTheirOwnEyeOfTheSameFrame) {
  const fs::path wall = fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-passive-2x1.toml";
  const int frames = 3, k = frames - 1;
  WallRun run("stereo",
              {"--wall", wall.string(), "--scene", "mesh", "--frames", std::to_string(frames),
               "--refresh", "0", "--path", "both", "--compare", "--keep", "last"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_NE(run.output().find("stereo: both eyes of 2 display pair(s) showed the same frame in "
                              "all "),
            std::string::npos)
      << run.output();

  expect_as_references(run, wall, k, 4);
  // Twins 0 (left) and 2 (right) show one canvas rectangle, from eyes 0.1 scene units apart.
  const fs::path shown = run.out() / fmt::format("frame-{}", k);
  const RgbImage left = read_png(shown / "display-0.png"),
                 right = read_png(shown / "display-2.png");
  EXPECT_GT(pixels_differing(left, right), 1000);
  expect_clean(run);
}

// An active wall (examples/walls/stereo-active-2x1.toml: two projectors, each showing both eyes
// one refresh after the other) on both paths: eye frames 4 and 5 are application frame 2's left
// and right eye, each display's front buffer holds each byte for byte as the pipeserver program
// renders that eye frame alone, and the summary says every display alternated left and right
// eye every refresh after the quad buffer, showing each of the 3 frames as a new pair (then again
// while no new one was ready); stereo-refreshes.csv says each refresh's eye and frame.
TEST(LiveRunStereo, ActiveDisplaysShowEachFramesLeftThenRightEye) {
  const fs::path wall = fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-active-2x1.toml";
  const int frames = 6;
  WallRun run("stereo-active",
              {"--wall", wall.string(), "--scene", "mesh", "--frames", std::to_string(frames),
               "--refresh", "0", "--path", "both", "--compare", "--keep", "4,5"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const auto summary = active_stereo_summary(run.output());
  ASSERT_TRUE(summary) << run.output();
  EXPECT_EQ(summary->shown - summary->repeated, 3) << run.output();
  // From the first pair on, two refreshes per pair shown, and the wall shows the last one whole.
  EXPECT_EQ(summary->refreshes, summary->first_pair + 2 * summary->shown) << run.output();
  const std::string refreshes = slurp(run.out() / "stereo-refreshes.csv");
  EXPECT_EQ(refreshes.rfind("refresh,eye,frame\n0,none,\n1,none,\n", 0), 0u) << refreshes;
  EXPECT_NE(refreshes.find(fmt::format("\n{},left,0\n{},right,0\n", summary->first_pair,
                                       summary->first_pair + 1)),
            std::string::npos)
      << refreshes;
  EXPECT_EQ(refreshes.substr(refreshes.size() - 9), ",right,2\n") << refreshes;

  for (const int k : {4, 5}) expect_as_references(run, wall, k, 2);
  // report.csv's rows are eye frames, each saying its eye.
  const std::string csv = slurp(run.out() / "report.csv");
  EXPECT_NE(csv.find(",eye\n0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",left\n5,"), std::string::npos) << csv;
  EXPECT_EQ(csv.substr(csv.size() - 7), ",right\n") << csv;
  // One display, one application frame, eyes 0.1 scene units apart.
  EXPECT_GT(pixels_differing(read_png(run.out() / "frame-4/display-0.png"),
                             read_png(run.out() / "frame-5/display-0.png")),
            1000);
  expect_clean(run);
}

TEST(LiveRunStereo, AnActiveWallRefusesAnOddFrameCount) {
  const fs::path wall = fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-active-2x1.toml";
  WallRun run("stereo-odd", {"--wall", wall.string(), "--frames", "3"});
  const ExitStatus status = run.wait(60s);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(run.output().find("--frames 3: an active stereo wall's frames are eye frames (left "
                              "and right of each application frame): give an even count"),
            std::string::npos)
      << run.output();
  expect_clean(run);
}

// A packed wall (side-by-side or top-bottom: each display shows both eyes, one in each half) on
// both paths: every display shows, byte for byte, the pipeserver program's reference (each half
// rendered alone with its eye's camera), the halves differ by the eyes' parallax, and the
// summary counts the frames every display showed with both eyes in its halves.
void expect_packed_run(const std::string& name, bool side) {
  const fs::path wall = fs::path(L2_SOURCE_DIR) / "examples/walls" / name;
  const int frames = 3, k = frames - 1;
  WallRun run("stereo-packed",
              {"--wall", wall.string(), "--scene", "mesh", "--frames", std::to_string(frames),
               "--refresh", "0", "--path", "both", "--compare", "--keep", "last"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_NE(run.output().find(fmt::format(
                "packed stereo ({}): each of 2 display(s) showed both eyes of each of its frames "
                "in its two halves in the same refresh ({}; every strip of it stamped with that "
                "frame), at least ",
                side ? "side-by-side" : "top-bottom",
                side ? "left half: left eye, right half: right eye"
                     : "top half: left eye, bottom half: right eye")),
            std::string::npos)
      << run.output();
  expect_as_references(run, wall, k, 2);
  // The halves of display 0 show one picture from eyes 0.1 scene units apart.
  const RgbImage shown = read_png(run.out() / fmt::format("frame-{}/display-0.png", k));
  const int w = side ? shown.width() / 2 : shown.width(),
            h = side ? shown.height() : shown.height() / 2;
  long differ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      differ += !(shown.at(x, y) == shown.at(side ? x + w : x, side ? y : y + h));
  EXPECT_GT(differ, 1000);
  expect_clean(run);
}

TEST(LiveRunStereo, SideBySideDisplaysShowBothEyesInTheirHalves) {
  expect_packed_run("stereo-side-by-side-2x1.toml", true);
}

TEST(LiveRunStereo, TopBottomDisplaysShowBothEyesInTheirHalves) {
  expect_packed_run("stereo-top-bottom-2x1.toml", false);
}

// What a packed wall cannot do is refused in one line: an odd width in the wall file, and a
// picture scene, whose pixels are drawn one to one.
TEST(LiveRunStereo, APackedWallRefusesAnOddWidthAndPicturesInOneLine) {
  const ScratchDir dir("stereo-packed");
  std::string text = slurp(fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-side-by-side-2x1.toml");
  text.replace(text.find("width = 640"), 11, "width = 641");
  std::ofstream(dir / "packed.toml") << text;
  WallRun odd("stereo-packed-odd", {"--wall", (dir / "packed.toml").string(), "--frames", "2"});
  EXPECT_FALSE(odd.wait(60s).ok());
  EXPECT_NE(odd.output().find("packed.toml:15: display 0: side-by-side stereo: width 641 is odd: "
                              "each eye takes exactly half of it"),
            std::string::npos)
      << odd.output();
  expect_clean(odd);
  const fs::path wall = fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-top-bottom-2x1.toml";
  write_png(dir / "grey.png", RgbImage(64, 48, Rgb{128, 128, 128}));
  WallRun picture("stereo-packed-picture",
                  {"--wall", wall.string(), "--scene", "picture", "--content",
                   (dir / "grey.png").string(), "--frames", "2"});
  EXPECT_FALSE(picture.wait(60s).ok());
  EXPECT_NE(picture.output().find("--scene picture: packed stereo walls (side-by-side, "
                                  "top-bottom) do not support it (its pixels are drawn one to "
                                  "one, not squeezed into each eye's half)"),
            std::string::npos)
      << picture.output();
  expect_clean(picture);
}

}  // namespace
}  // namespace l2
