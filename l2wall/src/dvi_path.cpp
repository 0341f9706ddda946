#include "dvi_path.hpp"

#include <algorithm>
#include <thread>

#include "l2wall/live_balance.hpp"

namespace l2 {

DviPath::DviPath(const Wall& wall, int threads, std::size_t pipeservers, double refresh_hz,
                 int frames, int drop_ready)
    : side_(wall, threads, pipeservers),
      clock_(refresh_hz),
      refresh_hz_(refresh_hz),
      frames_(frames),
      drop_ready_(drop_ready) {}

std::optional<PathSwap> DviPath::step(int, PipeserverSet& pipeservers,
                                      std::vector<FrameRecord>& records, const RunWatch& watch) {
  if (refresh_hz_ > 0) clock_.wait_next();
  watch.processes();
  const bool fresh = side_.take_in(pipeservers);
  pipeservers.serve_channels();
  if (balance_) balance_->serve(pipeservers);
  // As fast as possible still means "when there is something to do": re-reading unchanged
  // links would only take CPU from the pipeservers.
  if (refresh_hz_ == 0 && !fresh && !swap_due_) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    return std::nullopt;
  }
  const Emulator::Tick& tick = side_.refresh(pipeservers, records);
  swap_due_ = !tick.completed_groups.empty();
  if (balance_) count_for_balance(tick, pipeservers);
  // READY at once, in the refresh the frame completed (spec §6.4): a pipeserver with its next
  // frame rendered swaps it in now, and it is taken in at the next refresh.
  dropped_readies_ +=
      static_cast<std::uint64_t>(side_.send_readies(tick, pipeservers, drop_ready_));
  if (tick.swapped_groups.empty()) return std::nullopt;
  if (balance_) check_groups_for_balance(tick, pipeservers);
  PathSwap swap;
  swap.time = RunClock::now();
  swap.lowest = side_.lowest_frame_shown(pipeservers);
  swap.refresh = tick.index;
  shown_ = std::min(swap.lowest, frames_ - 1);
  return swap;
}

void DviPath::count_for_balance(const Emulator::Tick& tick, const PipeserverSet& pipeservers) {
  std::vector<std::uint64_t> routed(pipeservers.all().size(), 0);
  for (std::size_t i = 0; i < routed.size() && i < tick.kinds.size(); ++i) {
    if (tick.kinds[i] == FrameKind::New && i < tick.inputs.size())
      routed[i] = tick.inputs[i].routed_strips;
  }
  balance_->count_strips(pipeservers, routed);
}

// Each swapped group: the frames its displays show, by the stamps on them, must share a layout.
void DviPath::check_groups_for_balance(const Emulator::Tick& tick,
                                       const PipeserverSet& pipeservers) {
  for (const int id : tick.swapped_groups) {
    const auto& groups = side_.emulator_groups();
    const auto g = std::find_if(groups.begin(), groups.end(),
                                [&](const SwapGroup& sg) { return sg.id == id; });
    if (g == groups.end()) continue;
    balance_->check_swap(g->displays, pipeservers,
                         [&](const LivePipeserver& h) { return side_.frame_shown(h); });
  }
}

void DviPath::add_totals(RunTotals& totals) const {
  totals.refreshes = side_.refreshes();
  totals.frames_predicted = side_.emulator_report().frames_predicted;
  totals.predictions_missed = side_.emulator_report().predictions_missed;
  totals.dropped_readies += dropped_readies_;
}

}  // namespace l2
