// The DVI path as a display path (display_path.hpp): this process is the Lightning-2
// (LocalLightning2), paced by the refresh clock; it takes in every pipeserver's DVI link,
// refreshes, and sends READY in the refresh a frame completed (spec §6.4).
#pragma once

#include "dvi_link/refresh_clock.hpp"
#include "l2wall/display_path.hpp"
#include "l2wall/local_lightning2.hpp"

namespace l2 {

class DviPath final : public DisplayPath {
 public:
  DviPath(const Wall& wall, int threads, std::size_t pipeservers, double refresh_hz, int frames,
          int drop_ready);

  std::string label() const override { return "dvi"; }
  std::string name() const override { return "DVI path"; }
  void add_pipeserver_args(PipeserverLaunch& launch) const override { launch.dvi = true; }
  void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
            const RunWatch& watch) override {
    pipeservers.open_links(timeout, watch.processes);
  }

  bool refreshed() const override { return true; }
  std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                               std::vector<FrameRecord>& records, const RunWatch& watch) override;
  std::string pipeservers_wait_for() const override { return "READY"; }
  std::uint64_t inject_noise(PipeserverSet& pipeservers) override {
    return pipeservers.inject_noise();
  }

  DisplayPictures frame_pictures(int, const RunWatch&) override { return pictures(); }
  std::optional<DisplayPictures> shown() const override { return pictures(); }
  int frame_shown() const override { return shown_; }

  void add_totals(RunTotals& totals) const override;
  void follow_layouts(LiveBalance& balance, PipeserverSet&) override { balance_ = &balance; }

 private:
  void count_for_balance(const Emulator::Tick& tick, const PipeserverSet& pipeservers);
  void check_groups_for_balance(const Emulator::Tick& tick, const PipeserverSet& pipeservers);
  DisplayPictures pictures() const {
    return [this](int id) -> const RgbImage& { return side_.shown(id); };
  }

  LocalLightning2 side_;
  RefreshClock clock_;
  double refresh_hz_;
  int frames_;
  int drop_ready_;
  bool swap_due_ = false;
  int shown_ = -1;  // the frame the emulator's displays show
  std::uint64_t dropped_readies_ = 0;
  LiveBalance* balance_ = nullptr;
};

}  // namespace l2
