// The example walls in walls/ with the built-in scenes, as the parameters of the tests that
// sweep them (ExampleWall in example_walls_test.cpp, RenderersOnExampleWall in
// renderers_test.cpp): one test per wall and scene, so that ctest spreads them over the cores,
// each named "<wall>_<scene>".
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "pipeserver/scene.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::test {

using WallScene = std::tuple<std::filesystem::path, std::string>;

// The wall files of walls/ of one mesh, sorted. Walls of several meshes (hundreds of
// full-size panels) are planned and verified by tilelayout's tests, and run live at a small
// size by l2wall_run_meshes_tests.
inline std::vector<std::filesystem::path> example_walls() {
  std::vector<std::filesystem::path> out;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(L2_SOURCE_DIR) / "walls")) {
    if (e.path().extension() == ".toml" && load_wall(e.path()).mesh_count == 1)
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every example wall with every built-in scene, wall by wall.
inline std::vector<WallScene> all_wall_scenes() {
  std::vector<WallScene> out;
  for (const auto& wall : example_walls())
    for (const std::string& scene : built_in_scene_names()) out.emplace_back(wall, scene);
  return out;
}

// Each example wall with one scene and each scene on some wall: wall i with scene i % scenes,
// and when there are more scenes than walls, the scenes left over on the first walls again.
inline std::vector<WallScene> diagonal_wall_scenes() {
  const std::vector<std::filesystem::path> walls = example_walls();
  const std::vector<std::string>& scenes = built_in_scene_names();
  std::vector<WallScene> out;
  if (walls.empty() || scenes.empty()) return out;
  for (std::size_t i = 0; i < std::max(walls.size(), scenes.size()); ++i)
    out.emplace_back(walls[i % walls.size()], scenes[i % scenes.size()]);
  return out;
}

// The test's name: "<wall>_<scene>", with what gtest does not take in a name as '_'.
inline std::string wall_scene_name(const ::testing::TestParamInfo<WallScene>& info) {
  std::string n = std::get<0>(info.param).stem().string() + "_" + std::get<1>(info.param);
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

}  // namespace l2::test
