#include "cluster/rank_map.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lightning2_emu/mesh.hpp"

namespace l2 {

std::optional<int> RankMap::server_of(int rank) const {
  if (rank >= 1 && rank <= servers) return rank - 1;
  return std::nullopt;
}

std::optional<int> RankMap::column_of(int rank) const {
  if (rank > servers && rank < size()) return rank - 1 - servers;
  return std::nullopt;
}

std::string RankMap::role(int rank) const {
  if (rank == kCoordinator) return "coordinator";
  if (const auto s = server_of(rank)) return fmt::format("pipeserver {}", *s);
  if (const auto c = column_of(rank)) return fmt::format("board column {}", *c);
  return fmt::format("rank {} (none of the wall's roles)", rank);
}

RankMap make_rank_map(const TileLayout& layout) {
  const Wall& wall = layout.wall;
  const Mesh mesh = Mesh::fit(wall.server_count, static_cast<int>(wall.displays.size()),
                              {wall.board_max_width, wall.board_max_height});
  RankMap map;
  map.servers = static_cast<int>(layout.servers.size());
  map.columns = mesh.columns();
  map.mesh_inputs = mesh.input_count();
  map.columns_of_server.resize(static_cast<std::size_t>(map.servers));
  map.servers_of_column.resize(static_cast<std::size_t>(map.columns));
  map.displays_of_column.resize(static_cast<std::size_t>(map.columns));
  for (const Display& d : wall.displays)
    map.displays_of_column[static_cast<std::size_t>(Mesh::column_of_display(d.id))].push_back(d.id);
  for (auto& ids : map.displays_of_column) std::sort(ids.begin(), ids.end());
  for (const ServerPlan& plan : layout.servers) {
    auto& columns = map.columns_of_server[static_cast<std::size_t>(plan.server)];
    for (const PackedTile& t : plan.tiles)
      columns.push_back(Mesh::column_of_display(t.tile.display));
    // A host with no tile still shows a signal (only its headers' absence): column 0 takes it
    // in, as the one-machine emulator does, so it gets its READY.
    if (columns.empty()) columns.push_back(0);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    for (const int c : columns)
      map.servers_of_column[static_cast<std::size_t>(c)].push_back(plan.server);
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
      count(map.servers, "pipeserver"), count(map.columns, "board column"), ranks)};
}

}  // namespace l2
