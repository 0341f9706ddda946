// The emulated Lightning-2: a board mesh, its display buffers, swap-lock groups and the frame
// rules of spec §6, fed one scanned-out frame per input at every refresh ("tick").
//
//   tick t:  1. output refresh: groups completed during tick t-1 swap
//            2. the frames scanned out during t are parsed; new ones are routed
//            3. groups whose every feeding input has delivered are completed, and READY goes
//               to every host whose new frame's groups are all complete
// so a display shows during tick t+1 what was scanned out during tick t, and a host that swaps
// its next frame in at READY has it taken in at tick t+1: one new frame every refresh.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "lightning2_emu/frame_sequencer.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/swap_group.hpp"

namespace l2 {

struct EmulatorConfig {
  Mesh mesh{1, 1};
  std::vector<DisplaySpec> displays;  // swap_group: all 0 by default, i.e. one group
  Rgb background{};
  int workers = 0;              // 0: one per hardware thread
  bool predict_layouts = true;  // Router::predict_layouts()
};

// Per-run totals.
struct InputRunStats {
  int input = 0;
  std::array<std::uint64_t, 6> frames{};  // indexed by FrameKind
  std::uint64_t copy_strips = 0, key_strips = 0, depth_strips = 0, skip_strips = 0,
                routed_strips = 0;
  StripErrorCounts errors;  // over every frame seen, routed or not
  std::uint64_t count(FrameKind k) const { return frames[static_cast<int>(k)]; }
};
struct DisplayRunStats {
  int display = 0;
  std::uint64_t frames = 0;  // frames completed
  std::uint64_t strips = 0, covered_pixels = 0, overdraw_pixels = 0;
};
struct RunReport {
  std::uint64_t ticks = 0;
  // Frames predicted from their input's last layout (router.hpp), and how many of them turned
  // out different and were parsed.
  std::uint64_t frames_predicted = 0, predictions_missed = 0;
  std::vector<InputRunStats> inputs;
  std::vector<DisplayRunStats> displays;
  std::vector<SwapGroup> groups;  // with their swap counts
  std::uint64_t frames(FrameKind k) const {
    std::uint64_t n = 0;
    for (const auto& i : inputs) n += i.count(k);
    return n;
  }
};

class Emulator {
 public:
  explicit Emulator(const EmulatorConfig& config);

  struct Tick {
    std::uint64_t index = 0;
    std::vector<int> swapped_groups;  // group ids swapped at this tick's refresh
    std::vector<int> ready_inputs;    // hosts sent READY in this tick (their groups completed)
    std::vector<FrameKind> kinds;     // per input
    std::vector<InputFrameStats> inputs;
    std::vector<int> completed_groups;         // group ids completed during this tick
    std::vector<DisplayFrameStats> completed;  // their displays' frame statistics
  };
  // One refresh with one frame per input (fewer frames: the rest have no signal). The result
  // stays valid until the next call. Throws MeshError for a frame the mesh refuses.
  const Tick& tick(std::span<const InputFrame> frames);

  const RgbImage& shown(int display_id) const;  // the front buffer
  const Router& router() const { return router_; }
  const std::vector<SwapGroup>& groups() const { return report_.groups; }
  const RunReport& report() const { return report_; }

 private:
  // Reads the router's counts for this tick's frames into tick_.inputs and decides (nothing
  // committed).
  void decide(int inputs);

  WorkerPool pool_;
  Router router_;
  FrameSequencer sequencer_;
  std::vector<int> group_of_display_;  // by display index: group index
  std::vector<std::vector<int>> group_display_indices_;
  std::vector<int> swapped_;  // group indices
  FrameSequencer::Decision decision_;
  std::vector<FrameObservation> observations_;
  std::vector<DisplayFrameStats> finished_;
  Tick tick_;
  RunReport report_;
};

}  // namespace l2
