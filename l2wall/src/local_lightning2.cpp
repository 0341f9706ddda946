#include "l2wall/local_lightning2.hpp"
#include "lightning2_emu/wall_emulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "l2wall/frame_stamp.hpp"
#include "l2wall/run_fault.hpp"

namespace l2 {
LocalLightning2::LocalLightning2(const Wall& wall, int threads, std::size_t pipeservers)
    : emulator_(emulator_config(wall, threads)), inputs_(pipeservers) {}

void record_new_frames(PipeserverSet& pipeservers, std::vector<FrameRecord>& records,
                       std::span<const FrameKind> kinds,
                       const std::function<int(std::size_t)>& stamp, std::uint64_t refresh,
                       RunClock::time_point t0, double route_ms) {
  const int frames = static_cast<int>(records.size());
  std::vector<int> credited;  // frames this refresh's time is already counted in
  for (std::size_t i = 0; i < pipeservers.all().size(); ++i) {
    if (kinds.size() <= i || kinds[i] != FrameKind::New) continue;
    LivePipeserver& h = pipeservers.all()[i];
    h.accepted = stamp(i);
    if (h.accepted < 0 || h.accepted >= frames)
      throw RunFault(
          fmt::format("pipeserver {}: frame stamp {} out of range", h.pipeserver, h.accepted));
    FrameRecord& r = records[static_cast<std::size_t>(h.accepted)];
    if (std::find(credited.begin(), credited.end(), h.accepted) == credited.end()) {
      credited.push_back(h.accepted);
      r.route_ms += route_ms;  // once per frame, however many of its pipeservers came in now
    }
    r.in_refresh = refresh;  // the last input taken in decides
    r.in_time = t0;
  }
}

int send_readies(std::span<const int> ready_inputs, PipeserverSet& pipeservers, int drop_ready) {
  int held = 0;
  for (int i : ready_inputs) {
    LivePipeserver& h = pipeservers.all()[static_cast<std::size_t>(i)];
    if (i == 0 && h.accepted == drop_ready) {
      h.held_ready = h.accepted;  // lost on the line: the pipeserver must ask with SYNC?
      ++held;
      continue;
    }
    h.channel->send_ready(static_cast<std::uint64_t>(h.accepted));
  }
  return held;
}

const Emulator::Tick& LocalLightning2::refresh(PipeserverSet& pipeservers,
                                               std::vector<FrameRecord>& records) {
  const auto t0 = RunClock::now();
  const Emulator::Tick& tick = emulator_.tick(inputs_);
  const double route_ms = ms_between(t0, RunClock::now());
  ++refreshes_;
  record_new_frames(
      pipeservers, records, tick.kinds,
      [&](std::size_t i) {
        // A pipeserver delivers its frames in order: the new one is the one after the last, and its
        // layout says where its stamp is.
        const LivePipeserver& h = pipeservers.all()[i];
        const StampSpot& s = h.stamp(h.accepted + 1);
        return decode_stamp(inputs_[i].row(s.fb_y) + s.fb_x * 3);
      },
      tick.index, t0, route_ms);
  return tick;
}

int LocalLightning2::frame_shown(const LivePipeserver& h) const {
  // The displays show the frame the pipeserver delivered last, or (its next one taken in during the
  // swap's refresh) the one before; a balanced run may have moved the stamp between them.
  const auto read = [&](int frame) {
    const StampSpot& s = h.stamp(frame);
    return decode_stamp(emulator_.shown(s.display).row(s.dy).data() + s.dx * 3);
  };
  for (int frame : {h.accepted, h.accepted - 1}) {
    if (read(frame) == frame) return frame;
  }
  return read(h.accepted);
}

int LocalLightning2::lowest_frame_shown(const PipeserverSet& pipeservers) const {
  int lowest = 1 << 30;
  for (const LivePipeserver& h : pipeservers.serving()) lowest = std::min(lowest, frame_shown(h));
  return lowest;
}

int LocalLightning2::send_readies(const Emulator::Tick& tick, PipeserverSet& pipeservers,
                                  int drop_ready) {
  return l2::send_readies(tick.ready_inputs, pipeservers, drop_ready);
}

}  // namespace l2
