// The wide wall the content tests run on: three displays in a row, so a scene framed on the
// short side alone would leave the outer two black.
#pragma once

#include <filesystem>
#include <fstream>

namespace l2::testing_support {

// 3x1 displays of 160x120: a 4:1 canvas.
inline std::filesystem::path write_wide_wall(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "wide-3x1.toml";
  std::ofstream(path) << R"(name = "3x1 wide wall"
[display_grid]
columns = 3
rows = 1
width = 160
height = 120
[tiling]
kind = "kd"
tile_count = 6
[pipeservers]
count = 3
framebuffer_width = 200
framebuffer_height = 150
[mesh]
board_max_width = 1280
board_max_height = 1024
refresh_hz = 60
)";
  return path;
}

}  // namespace l2::testing_support
