// Your own model on the wall through `l2wall run`: a wide wall filled across every display,
// a glTF file's base colour on the displays, a model's degenerate faces left out and said once
// for the run, and a missing or damaged model refused in one line.
#include <gtest/gtest.h>

#include <regex>

#include "model_files.hpp"
#include "pipeserver/hostile_files.hpp"
#include "wall_run.hpp"
#include "wide_wall.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// Pixels of a display picture that are not background (black), the frame stamp aside.
long scene_pixels(const RgbImage& shown) {
  long n = 0;
  for (int y = 0; y < shown.height(); ++y)
    for (int x = 0; x < shown.width(); ++x) n += shown.at(x, y) != Rgb{} ? 1 : 0;
  return n;
}

// The sphere framed on the short side of a 4:1 canvas stayed on the middle display; every
// display shows part of the scene, on every scene: the generated ones fill the wide wall by
// default, a model with --fit fill (its default, fit, shows it whole: ModelOnTheWall).
class WideWall : public ::testing::TestWithParam<std::string> {};

TEST_P(WideWall, EveryDisplayShowsTheScene) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-wide-{}", getpid());
  fs::create_directories(dir);
  const fs::path wall = write_wide_wall(dir);
  std::vector<std::string> args{"--wall",   wall.string(), "--scene",   GetParam(),
                                "--frames", "3",           "--refresh", "0"};
  if (GetParam() == "mesh") args.insert(args.end(), {"--fit", "fill"});
  WallRun run("wide-" + GetParam(), args);
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int d = 0; d < 3; ++d) {
    const RgbImage shown = read_png(run.out() / "frame-2" / fmt::format("display-{}.png", d));
    // The bunny reaches about 30 columns into the outer displays at this frame; the frame
    // stamps are one pixel per pipeserver, the outer displays showed nothing else before.
    EXPECT_GT(scene_pixels(shown), 200) << GetParam() << " display " << d;
  }
  expect_clean(run);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, WideWall, ::testing::Values("mesh", "strips"));

// A glTF square with a green base colour, seen face on (no orbit): the displays show it in that
// colour's proportions (the light scales all three channels alike), nowhere the bunny's.
TEST(ModelOnTheWall, GltfBaseColourReachesTheDisplays) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-gltf-{}", getpid());
  fs::create_directories(dir);
  const float green[3] = {0.1f, 0.9f, 0.3f};
  write_gltf_square(dir / "square.gltf", green);
  WallRun run("gltf", {"--mesh", (dir / "square.gltf").string(), "--camera-orbit", "0", "--frames",
                       "2", "--refresh", "0"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  long square = 0, other = 0;
  for (int d = 0; d < 4; ++d) {
    const RgbImage shown = read_png(run.out() / "frame-1" / fmt::format("display-{}.png", d));
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        const Rgb p = shown.at(x, y);
        if (p == Rgb{}) continue;
        const bool proportional =
            p.g > 100 && std::abs(p.r * 9 - p.g) <= 12 && std::abs(p.b * 3 - p.g) <= 6;
        ++(proportional ? square : other);
      }
    }
  }
  // The square fills most of the 1300x980 canvas's middle; the frame stamps are the others.
  EXPECT_GT(square, 200000);
  EXPECT_LE(other, 4);
  expect_clean(run);
  fs::remove_all(dir);
}

// The same square on the wide wall (three displays side by side): with --fit fill it reaches
// every display, in its base colour; by default (fit) it is seen whole, on the middle display,
// the outer displays dark.
TEST(ModelOnTheWall, GltfModelSpansTheWideWall) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-gltf-wide-{}", getpid());
  fs::create_directories(dir);
  const float green[3] = {0.1f, 0.9f, 0.3f};
  write_gltf_square(dir / "square.gltf", green);
  const fs::path wall = write_wide_wall(dir);
  WallRun run("gltf-wide",
              {"--wall", wall.string(), "--mesh", (dir / "square.gltf").string(), "--camera-orbit",
               "0", "--frames", "2", "--refresh", "0", "--fit", "fill"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int d = 0; d < 3; ++d) {
    const RgbImage shown = read_png(run.out() / "frame-1" / fmt::format("display-{}.png", d));
    long square = 0;
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        const Rgb p = shown.at(x, y);
        square += p.g > 100 && std::abs(p.r * 9 - p.g) <= 12 && std::abs(p.b * 3 - p.g) <= 6;
      }
    }
    EXPECT_GT(square, 200) << "display " << d;
  }
  expect_clean(run);

  WallRun whole("gltf-whole", {"--wall", wall.string(), "--mesh", (dir / "square.gltf").string(),
                               "--camera-orbit", "0", "--frames", "2", "--refresh", "0"});
  ASSERT_TRUE(whole.wait(60s).ok()) << whole.output();
  for (int d = 0; d < 3; ++d) {
    const RgbImage shown = read_png(whole.out() / "frame-1" / fmt::format("display-{}.png", d));
    long square = 0, top_or_bottom = 0;
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        const Rgb p = shown.at(x, y);
        const bool green_pixel =
            p.g > 100 && std::abs(p.r * 9 - p.g) <= 12 && std::abs(p.b * 3 - p.g) <= 6;
        square += green_pixel;
        top_or_bottom += green_pixel && (y == 0 || y == shown.height() - 1);
      }
    }
    if (d == 1) {
      EXPECT_GT(square, 200) << "the middle display shows the square";
      EXPECT_EQ(top_or_bottom, 0) << "the square whole: not cut at the top or bottom";
    } else {
      EXPECT_EQ(square, 0) << "display " << d << " is outside a model seen whole";
    }
  }
  expect_clean(whole);
  fs::remove_all(dir);
}

// A model with a degenerate face runs, and the run says what it left out once: l2wall checks
// the model before starting the pipeservers and says it; they do not say it again.
TEST(ModelOnTheWall, DegenerateFacesAreSaidOncePerRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-degenerate-{}", getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "square.obj")
      << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\nf 2 3 3\n";
  WallRun run("degenerate",
              {"--mesh", (dir / "square.obj").string(), "--frames", "2", "--refresh", "0"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  const std::string line = (dir / "square.obj").string() +
                           ": 1 of 3 triangles degenerate (a vertex repeated), left out\n";
  const std::string output = run.output();
  const auto first = output.find(line);
  ASSERT_NE(first, std::string::npos) << output;
  EXPECT_EQ(output.find(line, first + 1), std::string::npos) << output;
  expect_clean(run);
  fs::remove_all(dir);
}

TEST(ModelOnTheWall, MissingOrDamagedModelIsOneLine) {
  WallRun missing("missing-model", {"--mesh", "/nonexistent/model.glb"});
  EXPECT_EQ(missing.wait(30s).code, 2);
  EXPECT_EQ(missing.output(),
            "l2wall: --mesh: File does not exist: /nonexistent/model.glb\nRun with --help for "
            "more information.\n");

  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-bad-{}", getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "cut.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\n"
                                    "property list uchar int vertex_indices\nend_header\n"
                                    "0 0 0\n1 0 0\n0 1 0\n3 0 1\n";
  WallRun damaged("damaged-model", {"--mesh", (dir / "cut.ply").string()});
  EXPECT_EQ(damaged.wait(30s).code, 1);
  EXPECT_EQ(damaged.output(),
            "l2wall: " + (dir / "cut.ply").string() +
                ": face 0 has vertex 0 twice in a row (a face line cut short?)\n");
  EXPECT_TRUE(damaged.pipeservers().empty());

  WallRun wrong_scene("wrong-scene", {"--scene", "strips", "--mesh", (dir / "cut.ply").string()});
  EXPECT_EQ(wrong_scene.wait(30s).code, 2);
  EXPECT_NE(wrong_scene.output().find("--mesh is an option of --scene mesh, not strips"),
            std::string::npos)
      << wrong_scene.output();
  fs::remove_all(dir);
}

// What would crash, hang or exhaust a pipeserver (pipeserver/tests/hostile/) is refused by the
// run's own look at the file, in one line, before any pipeserver starts: a glTF nested past any
// real scene, a PLY header cut short, a PNG claiming more pixels than its data holds (each
// pipeserver found that at its first row, after libpng's own line).
TEST(ModelOnTheWall, HostileContentIsRefusedBeforeAnyPipeserverStarts) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-hostile-{}", getpid());
  fs::create_directories(dir);
  const std::string ply = hostile::ply_header("ascii") + hostile::kPlyAsciiBody;
  hostile::write(dir / "deep.gltf", hostile::gltf(hostile::node_chain(20000)));
  hostile::write(dir / "cut.ply", ply.substr(0, 40));
  hostile::write(dir / "huge.png", hostile::png(100000, 100000, false, std::string(8, '\0')));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--mesh", (dir / "deep.gltf").string()},
       "deep.gltf: nodes nested 20000 deep (node 19999), more than the 1000 levels read here"},
      {{"--mesh", (dir / "cut.ply").string()},
       "cut.ply: the PLY header ends without end_header (cut short?)"},
      {{"--scene", "picture", "--content", (dir / "huge.png").string()},
       "huge.png: cannot read: a PNG of 100000x100000 pixels whose image data, 19 bytes, is too "
       "little to hold them (cut short or damaged)"},
  };
  for (const auto& [args, line] : cases) {
    WallRun run("hostile", args);
    EXPECT_EQ(run.wait(60s).code, 1) << line;
    EXPECT_EQ(run.output(), "l2wall: " + dir.string() + "/" + line + "\n");
    EXPECT_FALSE(fs::exists(run.out() / "pipeserver-0.log")) << "a pipeserver was started";
    expect_clean(run);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
