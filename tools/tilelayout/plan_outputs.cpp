#include "plan_outputs.hpp"

#include <fmt/format.h>

#include <iostream>

#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "tilelayout/pictures.hpp"

namespace l2 {

void write_pictures(const TileLayout& layout, const std::filesystem::path& dir) {
  make_folders(dir, "--png");
  for (const PipeserverPlan& s : layout.pipeservers) {
    const auto path = dir / fmt::format("pipeserver-{}.png", s.pipeserver);
    write_png(path, framebuffer_page(s));
    std::cout << "wrote " << path.string() << "\n";
  }
  write_png(dir / "wall.png", wall_page(layout));
  std::cout << "wrote " << (dir / "wall.png").string() << "\n";
  // A depth wall's layers cover the same canvas: one picture each (wall.png is layer 0).
  if (wall_layers(layout) == 1) return;
  for (int layer = 0; layer < wall_layers(layout); ++layer) {
    const auto path = dir / fmt::format("wall-layer-{}.png", layer);
    write_png(path, wall_page(layout, layer));
    std::cout << "wrote " << path.string() << "\n";
  }
}

void write_scanout(const TileLayout& layout, const std::filesystem::path& dir, bool parity,
                   PatternPlace place) {
  make_folders(dir, "--scanout");
  for (const PipeserverPlan& s : layout.pipeservers) {
    const auto path = dir / fmt::format("scanout-{}.png", s.pipeserver);
    write_png(path, test_frame(s, parity, place));
    std::cout << "wrote " << path.string() << "\n";
  }
}

}  // namespace l2
