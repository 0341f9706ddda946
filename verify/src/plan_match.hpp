// Whether each frame carries what its pipeserver's plan puts in it (spec §4): every strip at the
// planned place of the framebuffer with the planned header fields. The displays can be right
// while this is wrong: frames on crossed cables, or scanned out from another plan of the same
// wall, still route to the right pixels (every header says where its strip goes), but on a
// Lightning-2 READY then goes to the wrong pipeserver and the bus order changes where strips
// overlap. Private to the verifier.
#pragma once

#include <span>
#include <vector>

#include "found_strips.hpp"
#include "tilelayout/tile_layout.hpp"
#include "verify/routing_check.hpp"

namespace l2::verify_detail {

// Fills each input's planned size, not_as_planned, first_difference and carries. A scanline
// of a DEPTH tile sent sparse (tilelayout/sparse_depth.hpp) — DEPTH strips of its display row
// and SKIPs (`skips`), chained over exactly the tile's gap and payload columns — counts as the
// planned strip.
void match_plans(const TileLayout& layout, std::span<const FoundStrip> strips,
                 std::span<const FoundStrip> skips, std::vector<InputCheck>& inputs);

}  // namespace l2::verify_detail
