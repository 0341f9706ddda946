// Who does what in an MPI run of a wall, from rank order (docs/mpi-design.md): rank 0 the
// coordinator, ranks 1..S the pipeservers, ranks S+1..S+C the board columns of the wall's mesh
// (of each mesh in turn, for a wall of several: tilelayout/several_meshes.hpp).
// Which columns each pipeserver's frames go to (the DVI repeaters: only the columns whose
// displays its tiles land on). Pure logic: no MPI here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct RankMap {
  static constexpr int kCoordinator = 0;
  int pipeservers = 0;
  int columns = 0;
  int mesh_inputs = 0;
  std::vector<std::vector<int>> columns_of_pipeserver;  // ascending column numbers
  std::vector<std::vector<int>> pipeservers_of_column;  // ascending pipeserver numbers
  std::vector<std::vector<int>> displays_of_column;     // display ids, ascending
  std::vector<int> column_of_display;                   // by display id

  int size() const { return 1 + pipeservers + columns; }
  int pipeserver_rank(int pipeserver) const { return 1 + pipeserver; }
  int column_rank(int column) const { return 1 + pipeservers + column; }
  std::optional<int> pipeserver_of(int rank) const;
  std::optional<int> column_of(int rank) const;
  // "coordinator", "pipeserver 2", "board column 1"
  std::string role(int rank) const;
};

// Throws MeshError for a wall no mesh can take (as the one-machine run would).
// `every_column`: each pipeserver feeds every board column (a balanced run: a re-tiling may move
// its tiles onto any display), not only the columns of its first layout's tiles.
RankMap make_rank_map(const TileLayout& layout, bool every_column = false);

// The one-line error for an mpirun with the wrong number of ranks, or nullopt.
Status rank_count_error(const RankMap& map, int ranks);

}  // namespace l2
