// From a Wall to a TileLayout: cut the canvas into logical tiles, split them at display edges
// (dropping what mullions hide), hand them to pipeservers by the wall's policy and pack each
// pipeserver's framebuffer (spec §4).
#pragma once

#include <vector>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The whole plan. Throws LayoutError (file, line, what does not fit, and what would: see
// fit.hpp) when a pipeserver's tiles do not fit its framebuffer, a pipeserver gets no tile (it
// would scan out idle frames only, which never earn READY: spec §6) or the tiling cannot be
// cut. Uncovered display areas are warnings. Every program plans through here, so all accept
// and refuse the same walls with the same words.
TileLayout plan_layout(const Wall& wall);

// The same plan and checks with the pipeserver of every logical tile given (in tiling order)
// instead of the wall's assignment policy: the load balancer's choice. Sort-first walls
// without an overlay only; any other wall, a list of another length or a pipeserver out of
// range is a LayoutError.
TileLayout plan_layout(const Wall& wall, const std::vector<int>& pipeserver_of_logical);

// The same with the pipeservers in `gone` (ascending, no repeats) taking no part: a live run's
// host that died. They must be given no tile, and are the only ones planned without one (an
// empty PipeserverPlan); every other check is as above. A LayoutError names a gone pipeserver that
// was given a tile, or one out of range.
TileLayout plan_layout(const Wall& wall, const std::vector<int>& pipeserver_of_logical,
                       const std::vector<int>& gone);

// The steps of plan_layout, exposed so each can be checked on its own.

// Logical tiles on the canvas, in tiling order (row-major for grid and strips; k-d tiles in
// depth-first order, first half left/top).
std::vector<Rect> make_logical_tiles(const Wall& wall);

// Each logical tile intersected with each display (in display order), and on a packed stereo
// wall with each half of it (tilelayout/wall.hpp's display_parts); empty parts dropped.
std::vector<DisplayTile> split_at_displays(const Wall& wall, const std::vector<Rect>& logical);

// The pipeserver of each logical tile. `weights` is the work per tile (its visible pixels),
// used by AreaBalanced. Orders, then deals round-robin, except Blocks (contiguous runs of the
// raster order) and AreaBalanced (largest first to the least-loaded pipeserver):
//   RoundRobin: tiling order;  ZigZag: tile rows (same top edge) alternately left-to-right and
//   right-to-left;  Spiral: rings around the canvas centre, clockwise from the top-left.
std::vector<int> assign_pipeservers(AssignmentPolicy policy, const std::vector<Rect>& tiles,
                                    const std::vector<long long>& weights, int pipeserver_count,
                                    Rect canvas);

// The wall-file name of a policy: "round-robin", "zig-zag", "spiral", "blocks", "area-balanced".
const char* to_string(AssignmentPolicy policy);

// Layers every display tile is rendered as when the wall has `pipeserver_count` pipeservers: 1
// without [depth], else depth.layers ("all": every pipeserver but the overlay's).
int layer_count(const Wall& wall, int pipeserver_count);

// What assign_pipeservers gives `pipeserver_count` pipeservers under `policy`: each one's display
// tiles in packing order (tallest first, then tiling order), as pack_tiles takes them. In a
// depth wall the policy deals the logical tiles to the pipeservers of layer 0, G = (pipeservers
// that share the tiling) / layers of them, and pipeserver j·G + s renders layer j of what
// pipeserver s renders in layer 0, as DEPTH tiles; the overlay goes to the last pipeserver,
// alone. Every list is empty when the layers cannot share `pipeserver_count` pipeservers evenly.
std::vector<std::vector<DisplayTile>> pipeserver_tile_lists(const Wall& wall,
                                                            const std::vector<Rect>& logical,
                                                            const std::vector<DisplayTile>& tiles,
                                                            AssignmentPolicy policy,
                                                            int pipeserver_count);

}  // namespace l2
