// The meshes of a wall file: given per display or chosen, each mesh's pipeservers, and what a
// wall of several meshes cannot ask for yet.
#include <fmt/format.h>

#include <algorithm>

#include "tilelayout/several_meshes.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

// Where the wall's pipeserver count is written, for errors about it.
int pipeservers_line(const TomlFields& top) {
  const toml::table* table = top.table("pipeservers");
  const toml::node* count = table ? table->get("count") : nullptr;
  return count ? line_of(*count) : top.line_of("pipeservers");
}

// One line for what a wall of several meshes cannot do yet, at the line that asks for it.
void refuse_with_meshes(const TomlFields& top, const Wall& wall) {
  const auto refuse = [&](int line, std::string_view field, std::string_view what) {
    top.source().fail(line, field,
                      fmt::format("{} is for a wall of one mesh; this wall's {} displays need {} "
                                  "meshes",
                                  what, wall.displays.size(), wall.mesh_count));
  };
  if (wall.depth_layers != 0) refuse(wall.depth_line, "depth", "depth compositing");
  if (wall.overlay) refuse(wall.overlay->line, "overlay", "an overlay");
  if (wall.balance.balancing() || wall.balance.survive_host_loss) {
    refuse(wall.balance.line, "balance", "balancing");
  }
  if (wall.blend.on) refuse(wall.blend.line, "blend", "blending");
}

}  // namespace

void read_meshes(const TomlFields& top, Wall& wall) {
  const bool given = !wall.displays.empty() && wall.displays.front().mesh >= 0;
  if (!given) {
    const std::vector<int> mesh_of = choose_meshes(wall.displays);
    for (std::size_t i = 0; i < wall.displays.size(); ++i) wall.displays[i].mesh = mesh_of[i];
  }
  wall.mesh_count = 0;
  for (const Display& d : wall.displays) wall.mesh_count = std::max(wall.mesh_count, d.mesh + 1);
  wall.meshes_line = top.line_of(top.has("display_grid") ? "display_grid" : "display");
  if (wall.mesh_count == 1) {
    if (wall.pipeserver_count > kMaxPipeservers) {
      top.source().fail(pipeservers_line(top), "pipeservers.count",
                        fmt::format("{} is more than the {} inputs of a mesh",
                                    wall.pipeserver_count, kMaxPipeservers));
    }
    wall.mesh_pipeservers = {wall.pipeserver_count};
    return;
  }
  refuse_with_meshes(top, wall);
  if (wall.pipeserver_count < wall.mesh_count) {
    top.source().fail(pipeservers_line(top), "pipeservers.count",
                      fmt::format("{} pipeservers cannot feed {} meshes: each pipeserver feeds "
                                  "one mesh (its headers cannot say which) and each mesh needs "
                                  "one",
                                  wall.pipeserver_count, wall.mesh_count));
  }
  std::vector<long long> pixels(static_cast<std::size_t>(wall.mesh_count), 0);
  for (const Display& d : wall.displays) {
    pixels[static_cast<std::size_t>(d.mesh)] += 1LL * d.width * d.height;
  }
  wall.mesh_pipeservers = share_pipeservers(wall.pipeserver_count, pixels);
  for (int m = 0; m < wall.mesh_count; ++m) {
    const int share = wall.mesh_pipeservers[static_cast<std::size_t>(m)];
    if (share > kMaxPipeservers) {
      top.source().fail(pipeservers_line(top), "pipeservers.count",
                        fmt::format("mesh {} would take {} of the {} pipeservers, more than the "
                                    "{} inputs of a mesh",
                                    m, share, wall.pipeserver_count, kMaxPipeservers));
    }
  }
}

}  // namespace l2
