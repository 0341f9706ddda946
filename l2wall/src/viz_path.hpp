// The viz path as a display path (display_path.hpp): the compositing server
// process (VizserverProcess) composes the pipeservers' tiles; its swaps are the frames of this
// path, and the pipeservers wait for its SWAPPED instead of READY.
#pragma once

#include <memory>

#include "l2wall/display_path.hpp"
#include "vizserver_process.hpp"

namespace l2 {

class VizPath final : public DisplayPath {
 public:
  explicit VizPath(const VizLaunch& launch) : side_(std::make_unique<VizserverProcess>(launch)) {}

  std::string label() const override { return "vizserver"; }
  std::string name() const override { return "vizserver path"; }
  void add_pipeserver_args(PipeserverLaunch& launch) const override {
    launch.viz_address = side_->address();
    launch.env.push_back(side_->token_variable());
  }
  void open(PipeserverSet&, std::chrono::milliseconds, const RunWatch&) override {}

  bool refreshed() const override { return false; }
  std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                               std::vector<FrameRecord>& records, const RunWatch& watch) override;
  std::string pipeservers_wait_for() const override { return "SWAPPED"; }
  std::uint64_t inject_noise(PipeserverSet&) override { return 0; }

  DisplayPictures frame_pictures(int frame, const RunWatch& watch) override {
    return pictures(wait_for(frame, watch));
  }
  std::optional<DisplayPictures> shown() const override;
  int frame_shown() const override;

  bool down() override { return side_->down(); }
  void settle(std::chrono::milliseconds grace) override { side_->settle(grace); }
  Status failure_as_cause(int shown, const std::string& showing) override;
  Status failure(int shown, const std::string& showing) override {
    return Failure{side_->describe_down(shown, showing)};
  }
  Status hang_behind(const LivePipeserver& h, int shown, const std::string& showing) override;
  std::string process_name() const override { return side_->name(); }

  // The compositing server composes a frame from that frame's tiles only, so a swap never shows
  // two layouts: there is nothing to check, only the control channels to serve. No strip is
  // routed either: tiles travel whole.
  void follow_layouts(LiveBalance& balance, PipeserverSet& pipeservers) override;

  void lose_pipeserver(int pipeserver) override { side_->lose_pipeserver(pipeserver); }
  void finish() override;
  void shut_down() override { side_->shut_down(); }
  void add_totals(RunTotals&) const override {}

 private:
  // The compositing server's frame `frame`; while waiting, every process is still watched.
  viz::FramePtr wait_for(int frame, const RunWatch& watch);
  static DisplayPictures pictures(const viz::FramePtr& f) {
    return [f](int id) -> const RgbImage& { return f->displays.at(static_cast<std::size_t>(id)); };
  }

  std::unique_ptr<VizserverProcess> side_;
  LiveBalance* balance_ = nullptr;  // a balanced run's coordinator, and its pipeservers
  PipeserverSet* pipeservers_ = nullptr;
};

}  // namespace l2
