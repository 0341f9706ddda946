#include "dvi_path.hpp"

#include <algorithm>
#include <thread>

#include "l2wall/live_balance.hpp"

namespace l2 {

DviPath::DviPath(const Wall& wall, int threads, std::size_t hosts, double refresh_hz, int frames,
                 int drop_ready)
    : side_(wall, threads, hosts),
      clock_(refresh_hz),
      refresh_hz_(refresh_hz),
      frames_(frames),
      drop_ready_(drop_ready) {}

std::optional<PathSwap> DviPath::step(int, HostSet& hosts, std::vector<FrameRecord>& records,
                                      const RunWatch& watch) {
  if (refresh_hz_ > 0) clock_.wait_next();
  watch.processes();
  const bool fresh = side_.take_in(hosts);
  hosts.serve_channels();
  if (balance_) balance_->serve(hosts);
  // As fast as possible still means "when there is something to do": re-reading unchanged
  // links would only take CPU from the hosts.
  if (refresh_hz_ == 0 && !fresh && !swap_due_) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    return std::nullopt;
  }
  const Emulator::Tick& tick = side_.refresh(hosts, records);
  swap_due_ = !tick.completed_groups.empty();
  if (balance_) count_for_balance(tick, hosts);
  // READY at once, in the refresh the frame completed (spec §6.4): a host with its next
  // frame rendered swaps it in now, and it is taken in at the next refresh.
  dropped_readies_ += static_cast<std::uint64_t>(side_.send_readies(tick, hosts, drop_ready_));
  if (tick.swapped_groups.empty()) return std::nullopt;
  if (balance_) check_groups_for_balance(tick, hosts);
  PathSwap swap;
  swap.time = RunClock::now();
  swap.lowest = side_.lowest_frame_shown(hosts);
  swap.refresh = tick.index;
  shown_ = std::min(swap.lowest, frames_ - 1);
  return swap;
}

void DviPath::count_for_balance(const Emulator::Tick& tick, const HostSet& hosts) {
  std::vector<std::uint64_t> routed(hosts.hosts().size(), 0);
  for (std::size_t i = 0; i < routed.size() && i < tick.kinds.size(); ++i) {
    if (tick.kinds[i] == FrameKind::New && i < tick.inputs.size())
      routed[i] = tick.inputs[i].routed_strips;
  }
  balance_->count_strips(hosts, routed);
}

// Each swapped group: the frames its displays show, by the stamps on them, must share a layout.
void DviPath::check_groups_for_balance(const Emulator::Tick& tick, const HostSet& hosts) {
  for (const int id : tick.swapped_groups) {
    const auto& groups = side_.emulator_groups();
    const auto g = std::find_if(groups.begin(), groups.end(),
                                [&](const SwapGroup& sg) { return sg.id == id; });
    if (g == groups.end()) continue;
    balance_->check_swap(g->displays, hosts, [&](const Host& h) { return side_.frame_shown(h); });
  }
}

void DviPath::add_totals(RunTotals& totals) const {
  totals.refreshes = side_.refreshes();
  totals.frames_predicted = side_.emulator_report().frames_predicted;
  totals.predictions_missed = side_.emulator_report().predictions_missed;
  totals.dropped_readies += dropped_readies_;
}

}  // namespace l2
