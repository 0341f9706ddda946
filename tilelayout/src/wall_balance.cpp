// [balance]: how the tiling follows the load (balance/ does the balancing).
#include <fmt/format.h>

#include <vector>

#include "wall_sections.hpp"

namespace l2 {

void read_balance(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("balance");
  if (!table) return;
  const TomlFields f(*table, "balance", top.source(), {"mode", "assignment"});
  wall.balance.line = f.line();
  const std::vector<std::string_view> modes(std::begin(kBalanceModeNames),
                                            std::end(kBalanceModeNames));
  wall.balance.mode = static_cast<BalanceMode>(f.choice("mode", modes, 0));
  wall.balance.heaviest_first = f.choice("assignment", {"policy", "heaviest-first"}, 0) == 1;
  const bool balancing = wall.balance.mode != BalanceMode::Static || wall.balance.heaviest_first;
  // Depth and overlay tiles are shared out by layer and by rectangle, not by render time.
  if (balancing && (wall.depth_layers != 0 || wall.overlay)) {
    f.fail(f.has("mode") ? "mode" : "assignment",
           fmt::format("cannot balance a wall with [{}]: its tiles are shared by layer, not by "
                       "render time",
                       wall.depth_layers != 0 ? "depth" : "overlay"));
  }
}

}  // namespace l2
