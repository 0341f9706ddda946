// The acceptance check on every example wall in walls/ and every scene: the frames of
// all pipeservers decode with zero spec §3 errors, and routing their COPY strips rebuilds each
// display equal to its reference render (tolerance: see pipeserver/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

std::vector<std::filesystem::path> example_walls() {
  std::vector<std::filesystem::path> out;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(L2_SOURCE_DIR) / "walls")) {
    if (e.path().extension() == ".toml") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ExampleWalls, EverySceneReassemblesToTheReference) {
  const auto walls = example_walls();
  ASSERT_FALSE(walls.empty());
  for (const auto& path : walls) {
    const TileLayout layout = plan_layout(load_wall(path));
    for (const auto& name : scene_names()) {
      auto scene = make_scene(name, test::small_options());
      const int frame = 3;
      const auto check = test::check_wall(layout, *scene, frame);
      SCOPED_TRACE(path.filename().string() + " " + name);
      EXPECT_EQ(check.reassembly.errors.total(), 0u);
      EXPECT_EQ(check.reassembly.parities_seen, std::vector<int>{frame % 2});
      for (std::size_t d = 0; d < check.diffs.size(); ++d) {
        EXPECT_EQ(check.diffs[d].pixels_differing, 0)
            << "display " << d << " max channel diff " << check.diffs[d].max_channel_diff;
      }
    }
  }
}

}  // namespace
}  // namespace l2
