#include "mpi_link/rank_map.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {

std::optional<int> RankMap::pipeserver_of(int rank) const {
  if (rank >= 1 && rank <= pipeservers) return rank - 1;
  return std::nullopt;
}

std::optional<int> RankMap::column_of(int rank) const {
  if (rank > pipeservers && rank < size()) return rank - 1 - pipeservers;
  return std::nullopt;
}

std::string RankMap::role(int rank) const {
  if (rank == kCoordinator) return "coordinator";
  if (const auto s = pipeserver_of(rank)) return fmt::format("pipeserver {}", *s);
  if (const auto c = column_of(rank)) return fmt::format("board column {}", *c);
  return fmt::format("rank {} (none of the wall's roles)", rank);
}

RankMap make_rank_map(const TileLayout& layout, bool every_column) {
  const Wall& wall = layout.wall;
  const std::vector<MeshPart> meshes = meshes_of(layout);
  RankMap map;
  map.pipeservers = static_cast<int>(layout.pipeservers.size());
  map.column_of_display.assign(wall.displays.size(), 0);
  // Each mesh's columns in turn, a display in its mesh's column of its mesh id.
  for (const MeshPart& part : meshes) {
    const bool one = meshes.size() == 1;
    const Mesh mesh = wall_mesh(one ? wall : mesh_wall(wall, part));
    for (std::size_t k = 0; k < part.displays.size(); ++k) {
      const int own = one ? part.displays[k] : static_cast<int>(k);
      map.column_of_display[static_cast<std::size_t>(part.displays[k])] =
          map.columns + Mesh::column_of_display(own);
    }
    map.columns += mesh.columns();
    map.mesh_inputs = one ? mesh.input_count() : wall.pipeserver_count;
  }
  map.columns_of_pipeserver.resize(static_cast<std::size_t>(map.pipeservers));
  map.pipeservers_of_column.resize(static_cast<std::size_t>(map.columns));
  map.displays_of_column.resize(static_cast<std::size_t>(map.columns));
  for (const Display& d : wall.displays) {
    map.displays_of_column[static_cast<std::size_t>(map.column_of_display[d.id])].push_back(d.id);
  }
  for (auto& ids : map.displays_of_column) std::sort(ids.begin(), ids.end());
  for (const PipeserverPlan& plan : layout.pipeservers) {
    auto& columns = map.columns_of_pipeserver[static_cast<std::size_t>(plan.pipeserver)];
    for (const PackedTile& t : plan.tiles)
      columns.push_back(map.column_of_display[static_cast<std::size_t>(t.tile.display)]);
    // A host with no tile still shows a signal (only its headers' absence): its mesh's first
    // column takes it in, as the one-machine emulator does, so it gets its READY.
    if (columns.empty()) {
      const MeshPart& own = meshes[static_cast<std::size_t>(plan.mesh)];
      columns.push_back(
          own.displays.empty()
              ? 0
              : map.column_of_display[static_cast<std::size_t>(own.displays.front())]);
    }
    if (every_column) {
      columns.clear();
      for (int c = 0; c < map.columns; ++c) columns.push_back(c);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    for (const int c : columns)
      map.pipeservers_of_column[static_cast<std::size_t>(c)].push_back(plan.pipeserver);
  }
  return map;
}

Status rank_count_error(const RankMap& map, int ranks) {
  if (ranks == map.size()) return {};
  const auto count = [](int n, const char* what) {
    return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
  };
  return Failure{fmt::format(
      "--mpi: this wall needs mpirun -np {} (1 coordinator + {} + {}), got {} ranks", map.size(),
      count(map.pipeservers, "pipeserver"), count(map.columns, "board column"), ranks)};
}

}  // namespace l2
