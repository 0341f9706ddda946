#include "tilelayout/planner.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tilelayout/coverage.hpp"

namespace l2 {
namespace {

// A framebuffer row is as tall as its tallest tile, so packing tall tiles together wastes
// least: each pipeserver's list is sorted by height, tallest first, then in tiling order.
std::vector<DisplayTile> packing_order(std::vector<DisplayTile> tiles) {
  std::stable_sort(tiles.begin(), tiles.end(), [](const DisplayTile& a, const DisplayTile& b) {
    return a.on_display.h > b.on_display.h;
  });
  return tiles;
}

std::string where(const Wall& wall, int line) {
  if (wall.source.empty()) return "";
  if (line <= 0) return wall.source.string() + ": ";
  return fmt::format("{}:{}: ", wall.source.string(), line);
}

}  // namespace

TileLayout plan_layout(const Wall& wall) {
  TileLayout layout;
  layout.wall = wall;
  layout.logical_tiles = make_logical_tiles(wall);
  layout.tiles = split_at_displays(wall, layout.logical_tiles);

  std::vector<long long> visible(layout.logical_tiles.size(), 0);
  for (const DisplayTile& t : layout.tiles) visible[t.logical_tile] += t.on_display.area();
  const std::vector<int> server_of =
      assign_servers(wall.assignment, layout.logical_tiles, visible, wall.server_count,
                     {0, 0, wall.canvas_width, wall.canvas_height});

  std::vector<std::vector<DisplayTile>> lists(wall.server_count);
  for (const DisplayTile& t : layout.tiles) {
    layout.tile_server.push_back(server_of[t.logical_tile]);
    lists[server_of[t.logical_tile]].push_back(t);
  }
  for (int s = 0; s < wall.server_count; ++s) {
    try {
      layout.servers.push_back(pack_tiles(s, wall.framebuffer_width, wall.framebuffer_height,
                                          packing_order(std::move(lists[s]))));
    } catch (const LayoutError& e) {
      throw LayoutError(where(wall, wall.framebuffer_line) + e.what());
    }
  }
  for (const std::string& w : coverage_warnings(wall, display_coverage(wall, layout.tiles))) {
    layout.warnings.push_back(where(wall, 0) + "warning: " + w);
  }
  return layout;
}

}  // namespace l2
