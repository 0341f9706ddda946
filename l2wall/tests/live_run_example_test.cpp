// The example renderer (examples/spinning_cubes.cpp, a pipeserver of its own drawing) driven by
// `l2wall run --pipeserver`: the displays of a live run equal, pixel for pixel, the routing by
// lightning2_emu of the frames the same program writes on its own, and show its cubes.
#include <gtest/gtest.h>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

// Runs `argv` to the end; true when it exited 0.
bool run_to_end(const std::vector<std::string>& argv) {
  ChildProcess process(argv);
  const auto status = process.wait_for(60s);
  EXPECT_TRUE(status && status->ok())
      << argv.front() << ": " << (status ? status->describe() : "did not end");
  return status && status->ok();
}

TEST(ExampleRenderer, LiveFramesRouteExactlyAndShowItsDrawing) {
  const fs::path wall_file = fs::path(L2_SOURCE_DIR) / "walls" / "kd-2x2.toml";
  const int frames = 4, k = frames - 1;
  WallRun run("example", {"--wall", wall_file.string(), "--pipeserver-program", SPINNING_CUBES_PATH,
                          "--frames", std::to_string(frames), "--refresh", "0", "--keep", "last"});
  const ExitStatus status = run.wait(60s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();

  // The same frame from each pipeserver of the program, alone, routed by the emulator's tool.
  const fs::path dir = run.out().parent_path() / "alone";
  const Wall wall = load_wall(wall_file);
  const TileLayout layout = plan_layout(wall);
  std::vector<std::string> route{LIGHTNING2_EMU_PATH, "route", "--wall",
                                 wall_file.string(),  "--out", (dir / "routed").string()};
  for (const PipeserverPlan& plan : layout.pipeservers) {
    // pipeserver's --out is a folder: it writes scanout-<pipeserver>.png into it.
    const fs::path frame = dir / fmt::format("scanout-{}.png", plan.pipeserver);
    ASSERT_TRUE(run_to_end({SPINNING_CUBES_PATH, "--wall", wall_file.string(), "--pipeserver",
                            std::to_string(plan.pipeserver), "--frame", std::to_string(k), "--out",
                            dir.string()}));
    route.push_back(frame.string());
  }
  ASSERT_TRUE(run_to_end(route));

  for (const Display& d : wall.displays) {
    const RgbImage shown =
        read_png(run.out() / fmt::format("frame-{}", k) / fmt::format("display-{}.png", d.id));
    const RgbImage routed = read_png(dir / "routed" / fmt::format("display-{}.png", d.id));
    ASSERT_EQ(shown.width(), routed.width());
    ASSERT_EQ(shown.height(), routed.height());
    // Each live pipeserver stamps its frame number into the first pixel of its first tile.
    std::vector<std::pair<int, int>> stamps;
    for (const PipeserverPlan& plan : layout.pipeservers) {
      const DisplayTile& t = plan.tiles.front().tile;
      if (t.display == d.id) stamps.emplace_back(t.on_display.x, t.on_display.y);
    }
    long differ = 0, drawn = 0;
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        if (std::find(stamps.begin(), stamps.end(), std::pair{x, y}) != stamps.end()) continue;
        differ += !(shown.at(x, y) == routed.at(x, y));
        drawn += !(routed.at(x, y) == Rgb{});
      }
    }
    EXPECT_EQ(differ, 0) << "display " << d.id;
    // The ring of cubes crosses the middle of the 2x2 wall: every display shows part of it.
    EXPECT_GT(drawn, shown.width() * shown.height() / 50) << "display " << d.id;
  }
  expect_clean(run);
}

}  // namespace
}  // namespace l2
