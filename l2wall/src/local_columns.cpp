#include "local_columns.hpp"

#include <fmt/format.h>

#include <numeric>

#include "lightning2_emu/wall_emulator.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {

LocalColumns::LocalColumns(const Wall& wall, int threads, std::size_t pipeservers)
    : pool_(threads), inputs_(pipeservers) {
  const std::vector<MeshPart> meshes = mesh_parts(wall);
  const bool predict = meshes.size() == 1;
  mesh_of_display_.assign(wall.displays.size(), 0);
  for (const MeshPart& m : meshes) {
    for (const int id : m.displays) mesh_of_display_[static_cast<std::size_t>(id)] = m.mesh;
    // One mesh takes every input the path has (a run may have fewer pipeservers than the wall
    // file says); several take their own.
    std::vector<int> inputs(meshes.size() == 1 ? pipeservers
                                               : static_cast<std::size_t>(m.pipeserver_count));
    std::iota(inputs.begin(), inputs.end(), meshes.size() == 1 ? 0 : m.first_pipeserver);
    for (const int p : inputs) {
      if (static_cast<std::size_t>(p) >= mesh_of_input_.size())
        mesh_of_input_.resize(static_cast<std::size_t>(p) + 1, 0);
      mesh_of_input_[static_cast<std::size_t>(p)] = m.mesh;
    }
    columns_.push_back(
        std::make_unique<BoardColumn>(wall, m.displays, std::move(inputs), pool_, predict));
  }
  seen_.resize(columns_.size());
  if (meshes.size() == 1) return;
  meshes_line_ = fmt::format(
      "meshes: {} emulated in this process, each with its own display ids and pipeservers, "
      "swapped by one frame-lock signal (the swap lock above spans them)\n",
      meshes.size());
  for (const MeshPart& m : meshes) {
    meshes_line_ += fmt::format("  mesh {}: wall displays {}; pipeservers {}-{}\n", m.mesh,
                                number_runs(m.displays), m.first_pipeserver,
                                m.first_pipeserver + m.pipeserver_count - 1);
  }
}

const BoardColumn& LocalColumns::column_of_display(int id) const {
  const auto i = static_cast<std::size_t>(id);
  return *columns_.at(i < mesh_of_display_.size() ? static_cast<std::size_t>(mesh_of_display_[i])
                                                  : 0);
}

const BoardColumn& LocalColumns::column_of_input(int pipeserver) const {
  const auto i = static_cast<std::size_t>(pipeserver);
  return *columns_.at(i < mesh_of_input_.size() ? static_cast<std::size_t>(mesh_of_input_[i]) : 0);
}

Status LocalColumns::refresh(const Tick& tick, PipeserverSet&, const Decide& decide,
                             const std::function<void(std::span<const Observation>)>&) {
  for (auto& c : columns_) {
    c->swap(tick.swapped_groups);
    c->scan(inputs_, tick);
  }
  const ColumnRoute* chosen = nullptr;
  if (columns_.size() == 1) {
    BoardColumn& column = *columns_.front();
    column.write([&] {
      seen_.front() = column.observe(tick.refresh);
      chosen = &decide(seen_);
      return std::span<const std::uint8_t>(chosen->route);
    });
  } else {
    // Every mesh parses every frame (no prediction), so what they saw is known before writing.
    for (std::size_t i = 0; i < columns_.size(); ++i) seen_[i] = columns_[i]->observe(tick.refresh);
    chosen = &decide(seen_);
    for (auto& c : columns_) c->write([&] { return std::span<const std::uint8_t>(chosen->route); });
  }
  for (auto& c : columns_) c->complete(chosen->completed_groups);
  return {};
}

void LocalColumns::add_totals(RunTotals& totals) const {
  for (const auto& c : columns_) {
    totals.frames_predicted += c->router().predictions().predicted;
    totals.predictions_missed += c->router().predictions().mispredicted;
  }
}

}  // namespace l2
