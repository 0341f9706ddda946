#include "l2wall/viz_path.hpp"

#include "l2wall/live_balance.hpp"
#include "l2wall/run_fault.hpp"

namespace l2 {

void VizPath::follow_layouts(LiveBalance& balance, PipeserverSet& pipeservers) {
  balance.strips_not_counted("the vizserver path sends whole tiles, no strips");
  balance.swaps_not_checked("the compositing server composes every frame from its own tiles");
  balance_ = &balance;
  pipeservers_ = &pipeservers;
}

std::optional<PathSwap> VizPath::step(int next, PipeserverSet&, std::vector<FrameRecord>&,
                                      const RunWatch& watch) {
  wait_for(next, watch);
  PathSwap swap;
  swap.lowest = next;
  swap.time = RunClock::now();
  return swap;
}

void VizPath::wait_for(int frame, const RunWatch& watch) {
  // Compositors that bound a frame's time name themselves late; the others are named by the
  // run's stall check, which the wait keeps running.
  const auto limit = compositors_->frame_limit();
  const auto deadline = RunClock::now() + limit.value_or(std::chrono::milliseconds(0));
  for (;;) {
    if (balance_) balance_->serve(*pipeservers_);
    if (compositors_->composed(frame, std::chrono::milliseconds(20))) return;
    if (!limit) {
      watch.waiting();
      continue;
    }
    watch.processes();
    if (RunClock::now() > deadline) throw RunFault(compositors_->late(frame));
  }
}

}  // namespace l2
