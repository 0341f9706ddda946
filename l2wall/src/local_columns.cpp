#include "local_columns.hpp"

#include <numeric>

#include "lightning2_emu/wall_emulator.hpp"

namespace l2 {
namespace {

std::vector<int> every_input(std::size_t pipeservers) {
  std::vector<int> inputs(pipeservers);
  std::iota(inputs.begin(), inputs.end(), 0);
  return inputs;
}

}  // namespace

LocalColumns::LocalColumns(const Wall& wall, int threads, std::size_t pipeservers)
    : pool_(threads),
      column_(wall, display_ids(wall), every_input(pipeservers), pool_, /*predict=*/true),
      inputs_(pipeservers),
      seen_(1) {}

Status LocalColumns::refresh(const Tick& tick, PipeserverSet&, const Decide& decide,
                             const std::function<void(std::span<const Observation>)>&) {
  column_.swap(tick.swapped_groups);
  column_.scan(inputs_, tick);
  const ColumnRoute* chosen = nullptr;
  column_.write([&] {
    seen_.front() = column_.observe(tick.refresh);
    chosen = &decide(seen_);
    return std::span<const std::uint8_t>(chosen->route);
  });
  column_.complete(chosen->completed_groups);
  return {};
}

void LocalColumns::add_totals(RunTotals& totals) const {
  totals.frames_predicted = column_.router().predictions().predicted;
  totals.predictions_missed = column_.router().predictions().mispredicted;
}

}  // namespace l2
