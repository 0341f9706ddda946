// A board column as an MPI rank: the boards of one column of the wall's mesh, taking in the
// frames of the pipeservers whose tiles land on its displays, routing their strips into its
// up-to-8 displays, and swapping them when the coordinator says so. It runs the coordinator's
// commands in order: a refresh's take-in and scan (answered with what it saw), the route and
// completion decided from every column's observations, a fetch of its displays, the end.
// With the viz path it also composites the tiles the pipeservers send for
// its displays (the compositing server's FrameAssembler), between and during commands. With
// --show monitors it shows its displays on its own machine's monitors after every swap.
#pragma once

#include "column_show.hpp"
#include "l2wall/live_run.hpp"
#include "mpi_link/rank_map.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Returns the exit code. From `o`: --threads; --path both (the viz path runs
// too, and this column composites the tiles of its displays). `show`: --show monitors, shown
// after every swap, or null.
int run_column(const TileLayout& layout, const RankMap& map, int column, const RunOptions& o,
               ColumnShow* show);

}  // namespace l2
