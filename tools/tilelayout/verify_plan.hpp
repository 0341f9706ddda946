// `tilelayout WALL --verify DIR`: the plan scanned out, routed through the emulated mesh and
// every display pixel checked against the plan, in one step.
#pragma once

#include <filesystem>
#include <string_view>

#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Writes DIR/scanout-<n>.png, DIR/display-<d>.png and DIR/verify-<d>.png, prints the report,
// each line after `prefix` (a mesh's "mesh 2: ", so that every wrong strip names its mesh);
// returns 0 when the routing is right, kExitRoutingWrong otherwise. Throws std::runtime_error
// when a file cannot be written.
int verify_plan(const TileLayout& layout, const std::filesystem::path& dir, bool parity,
                std::string_view prefix = "");

}  // namespace l2
