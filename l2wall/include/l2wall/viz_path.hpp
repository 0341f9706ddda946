// The viz path as a display path (display_path.hpp), written once for every backend: the
// pipeservers' tiles are composed into displays by the compositors (compositors.hpp: the
// compositing server process, or the board column ranks over MPI); a frame is on this path's
// displays once it is composed everywhere, and the pipeservers wait for SWAPPED instead of READY.
//
// Owns: the wait for a frame while the run is watched, and the balance hooks (the control
// channels served while waiting). It may not touch tiles or pixels: the compositors do.
#pragma once

#include <memory>

#include "l2wall/colour_stage.hpp"
#include "l2wall/compositors.hpp"
#include "l2wall/display_path.hpp"

namespace l2 {

class VizPath final : public DisplayPath {
 public:
  // `colour`: the wall's colour matching (colour_stage.hpp), the same the DVI path applies.
  explicit VizPath(std::unique_ptr<Compositors> compositors, ColourStage colour = {})
      : compositors_(std::move(compositors)), colour_(std::move(colour)) {}

  std::string label() const override { return "vizserver"; }
  std::string name() const override { return "vizserver path"; }
  void add_pipeserver_args(PipeserverLaunch& launch) const override {
    compositors_->add_pipeserver_args(launch);
  }
  void open(PipeserverSet&, std::chrono::milliseconds, const RunWatch&) override {}

  bool refreshed() const override { return false; }
  std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                               std::vector<FrameRecord>& records, const RunWatch& watch) override;
  std::string pipeservers_wait_for() const override { return "SWAPPED"; }
  std::uint64_t inject_noise(PipeserverSet&) override { return 0; }

  DisplayPictures frame_pictures(int frame, const RunWatch& watch) override {
    wait_for(frame, watch);
    return colour_.apply(compositors_->pictures(frame), frame);
  }
  // Far displays stay where they are: composed is enough.
  void take_frame(int frame, const RunWatch& watch) override { wait_for(frame, watch); }
  std::optional<DisplayPictures> shown() const override {
    auto pictures = compositors_->shown();
    if (!pictures) return std::nullopt;
    return colour_.apply(std::move(*pictures));
  }
  int frame_shown() const override { return compositors_->frame_shown(); }

  bool down() override { return compositors_->down(); }
  void settle(std::chrono::milliseconds grace) override { compositors_->settle(grace); }
  Status failure_as_cause(int shown, const std::string& showing) override {
    return compositors_->failure_as_cause(shown, showing);
  }
  Status failure(int shown, const std::string& showing) override {
    return compositors_->failure(shown, showing);
  }
  Status hang_behind(const LivePipeserver& h, int shown, const std::string& showing) override {
    return compositors_->hang_behind(h, shown, showing);
  }
  std::string process_name() const override { return compositors_->process_name(); }

  // The compositors compose a frame from that frame's tiles only, so a swap never shows two
  // layouts: there is nothing to check, only the control channels to serve. No strip is routed
  // either: tiles travel whole.
  void follow_layouts(LiveBalance& balance, PipeserverSet& pipeservers) override;
  void lose_pipeserver(int pipeserver) override { compositors_->lose(pipeserver); }
  void finish() override { compositors_->finish(); }
  void shut_down() override { compositors_->shut_down(); }
  // Beside a DVI path, that one paces the run.
  void add_totals(RunTotals& totals) const override {
    if (totals.pace.empty()) totals.pace = "no emulator refresh: the compositing server swaps";
  }

 private:
  // Until frame `frame` is composed everywhere; meanwhile every process is still watched.
  void wait_for(int frame, const RunWatch& watch);

  std::unique_ptr<Compositors> compositors_;
  ColourStage colour_;
  LiveBalance* balance_ = nullptr;  // a balanced run's coordinator, and its pipeservers
  PipeserverSet* pipeservers_ = nullptr;
};

}  // namespace l2
