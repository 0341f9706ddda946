// A passive stereo wall run live (examples/walls/stereo-passive-2x1.toml: two projectors per eye,
// each left-eye projector with a right-eye twin on its canvas rectangle), on both paths: every
// display shows, byte for byte, what the pipeserver program renders alone as that display's
// reference (its own eye's camera), the two eyes differ, and the summary says the swap-lock
// check proved both eyes of every frame shown together in every refresh.
#include <gtest/gtest.h>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

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

  // Each display's reference render of frame k by the pipeserver program alone.
  const fs::path references = run.out().parent_path() / "references";
  ChildProcess reference({PIPESERVER_EXE, "--wall", wall.string(), "--scene", "mesh", "--frame",
                          std::to_string(k), "--reference", references.string()});
  const auto ended = reference.wait_for(120s);
  ASSERT_TRUE(ended && ended->ok()) << (ended ? ended->describe() : "did not end");

  const fs::path shown = run.out() / fmt::format("frame-{}", k);
  for (int d = 0; d < 4; ++d) {
    const RgbImage want = read_png(references / fmt::format("display-{}.png", d));
    EXPECT_TRUE(read_png(shown / fmt::format("display-{}.png", d)) == want) << "display " << d;
    EXPECT_TRUE(read_png(shown / fmt::format("display-{}-vizserver.png", d)) == want)
        << "display " << d;
  }
  // Twins 0 (left) and 2 (right) show one canvas rectangle, from eyes 0.1 scene units apart.
  const RgbImage left = read_png(shown / "display-0.png"),
                 right = read_png(shown / "display-2.png");
  long differ = 0;
  for (int y = 0; y < left.height(); ++y)
    for (int x = 0; x < left.width(); ++x) differ += !(left.at(x, y) == right.at(x, y));
  EXPECT_GT(differ, 1000);
  expect_clean(run);
}

TEST(LiveRunStereo, AModeNotDoneYetIsRefusedInOneLine) {
  const ScratchDir dir("stereo-active");
  std::string text = slurp(fs::path(L2_SOURCE_DIR) / "examples/walls/stereo-passive-2x1.toml");
  text.replace(text.find("mode = \"passive\""), 16, "mode = \"active\"");
  std::ofstream(dir / "active.toml") << text;
  WallRun run("stereo-active", {"--wall", (dir / "active.toml").string(), "--frames", "2"});
  const ExitStatus status = run.wait(60s);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(run.output().find("active.toml:8: stereo: stereo walls do not support \"active\" "
                              "(only \"passive\") yet"),
            std::string::npos)
      << run.output();
  expect_clean(run);
}

}  // namespace
}  // namespace l2
