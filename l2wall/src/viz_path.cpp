#include "viz_path.hpp"

#include <fmt/format.h>

#include "l2wall/live_balance.hpp"
#include "pipeserver/live_exit.hpp"

namespace l2 {

using std::chrono::milliseconds;

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

viz::FramePtr VizPath::wait_for(int frame, const RunWatch& watch) {
  for (;;) {
    if (balance_) balance_->serve(*pipeservers_);
    if (viz::FramePtr f = side_->frame(frame, milliseconds(20))) return f;
    watch.waiting();
  }
}

std::optional<DisplayPictures> VizPath::shown() const {
  if (!side_->last()) return std::nullopt;
  return pictures(side_->last());
}

int VizPath::frame_shown() const {
  return side_->last() ? static_cast<int>(side_->last()->frame) : -1;
}

Status VizPath::failure_as_cause(int shown, const std::string& showing) {
  if (side_->down() && !side_->said_why()) return Failure{side_->describe_down(shown, showing)};
  return {};
}

// A pipeserver waits for SWAPPED only ready-timeout x retries, often less than --stall-timeout: one
// that gave up on a server still running means the server hangs.
Status VizPath::hang_behind(const LivePipeserver& h, int shown, const std::string& showing) {
  if (side_->down() || !h.exit || h.exit->code != kExitLostCompositingServer) return {};
  return Failure{
      fmt::format("the {} stopped answering: pipeserver {} gave up waiting for it at frame {}; {}",
                  side_->name(), h.pipeserver, shown, showing)};
}

void VizPath::finish() {
  side_->finish(milliseconds(5000));
}

}  // namespace l2
