// The DVI path of a live run: this process is the Lightning-2. It takes in every pipeserver's DVI
// link, ticks the emulator (routing, swap-lock groups), reads from the pixels which frame each
// pipeserver delivered and which frame the displays show, and sends READY over the back-channels.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_report.hpp"
#include "lightning2_emu/emulator.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The parts of a refresh every Lightning-2 of a live run shares, in one process or over MPI
// ranks (cluster/): for each pipeserver whose frame is new in refresh `refresh`, its frame stamp
// (`stamp(i)` for pipeserver i) becomes LivePipeserver::accepted and that frame's record gets the
// refresh and the route time (once per frame). Throws RunFault for a stamp outside 0..frames-1.
void record_new_frames(PipeserverSet& pipeservers, std::vector<FrameRecord>& records,
                       std::span<const FrameKind> kinds,
                       const std::function<int(std::size_t)>& stamp, std::uint64_t refresh,
                       RunClock::time_point t0, double route_ms);
// READY for the frame accepted from each pipeserver of `ready_inputs`. Fault injection: pipeserver
// 0's READY of frame `drop_ready` is held back until it asks with SYNC?. Returns how many READYs
// were held back.
int send_readies(std::span<const int> ready_inputs, PipeserverSet& pipeservers, int drop_ready);

class LocalLightning2 {
 public:
  LocalLightning2(const Wall& wall, int threads, std::size_t pipeservers);

  // Takes in every link; true when some link has a frame not seen before.
  bool take_in(PipeserverSet& pipeservers) { return pipeservers.take_in(inputs_); }
  // One refresh: routes what was taken in, and records for each pipeserver's new input the frame
  // its stamp says (LivePipeserver::accepted, the record's refresh and route time). Throws RunFault
  // for a stamp outside 0..frames-1.
  const Emulator::Tick& refresh(PipeserverSet& pipeservers, std::vector<FrameRecord>& records);
  // The lowest frame the displays show, read from every pipeserver's stamp on them: measured, not
  // assumed.
  int lowest_frame_shown(const PipeserverSet& pipeservers) const;
  // READY for the frame the emulator accepted from each pipeserver whose groups completed in this
  // tick (on the displays from the next refresh on). Fault injection: pipeserver 0's READY of frame
  // `drop_ready` is held back until it asks with SYNC?. Returns how many READYs were held back.
  int send_readies(const Emulator::Tick& tick, PipeserverSet& pipeservers, int drop_ready);

  const RgbImage& shown(int display) const { return emulator_.shown(display); }
  std::uint64_t refreshes() const { return refreshes_; }
  const RunReport& emulator_report() const { return emulator_.report(); }
  const std::vector<SwapGroup>& emulator_groups() const { return emulator_.groups(); }

  // The frame pipeserver `h`'s stamp on the displays says.
  int frame_shown(const LivePipeserver& h) const;

 private:
  Emulator emulator_;
  std::vector<InputFrame> inputs_;
  std::uint64_t refreshes_ = 0;
};

}  // namespace l2
