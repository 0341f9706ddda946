// A model of over a million triangles, made by the test, rendered live on the default wall,
// with the bucketing's overlap factor in every pipeserver's report.
#include <gtest/gtest.h>

#include <regex>

#include "model_files.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

TEST(LargeModel, MillionTriangleSphereRendersLive) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-large-{}", getpid());
  fs::create_directories(dir);
  const long triangles = write_ply_sphere(dir / "sphere.ply", 512, 1000);
  ASSERT_GE(triangles, 1'000'000);
  // A frame of a million triangles on each of four pipeservers can take seconds on a loaded
  // machine: more than the default stall timeout allows between two swaps.
  WallRun run("large-model", {"--mesh", (dir / "sphere.ply").string(), "--frames", "3", "--refresh",
                              "0", "--stall-timeout", "60000"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  EXPECT_NE(run.output().find("3 frames on 4 displays from 4 pipeservers"), std::string::npos)
      << run.output();
  for (int d = 0; d < 4; ++d) {
    const RgbImage shown = read_png(run.out() / "frame-2" / fmt::format("display-{}.png", d));
    long lit = 0;
    for (int y = 0; y < shown.height(); ++y)
      for (int x = 0; x < shown.width(); ++x) lit += shown.at(x, y) != Rgb{} ? 1 : 0;
    EXPECT_GT(lit, shown.width() * shown.height() / 4) << "display " << d;
  }
  // The sphere's 27 batches reach every tile, each drawn into a tile only where its box
  // projects: the overlap factor (tile draws / batches) lies between 1 and the pipeserver's tiles.
  const TileLayout layout = plan_layout(default_wall());
  const std::regex figures("batches ([0-9]+) tile_draws ([0-9]+) overlap ([0-9.]+)");
  for (const PipeserverPlan& plan : layout.pipeservers) {
    const std::string log = slurp(run.out() / fmt::format("pipeserver-{}.log", plan.pipeserver));
    int frames = 0;
    for (auto it = std::sregex_iterator(log.begin(), log.end(), figures);
         it != std::sregex_iterator(); ++it, ++frames) {
      const long batches = std::stol((*it)[1]), draws = std::stol((*it)[2]);
      EXPECT_GT(batches, 0) << log;
      EXPECT_GE(draws, batches);
      EXPECT_LE(draws, batches * static_cast<long>(plan.tiles.size()));
      EXPECT_NEAR(std::stod((*it)[3]), static_cast<double>(draws) / static_cast<double>(batches),
                  0.006);
    }
    EXPECT_EQ(frames, 3) << log;
  }
  expect_clean(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
