// Spec §6 as a state machine, pure logic: which input frames are new, repeated, torn or idle,
// which are routed, when a swap-lock group swaps and which hosts get READY. It sees frames only
// through their parsed summaries, so it is tested without any pixels.
//
// Decisions the spec leaves open, made here:
//  - An input "feeds" a group when its frame has a COPY strip that reaches a display of it.
//  - A frame with the accepted parity is a repeat (the host is still waiting for READY): it is
//    not routed again and holds up every group it feeds that has not received its new frame.
//  - A new parity from a host that has not had READY yet (it did not wait) is "early": not
//    accepted, not routed; the same frame is accepted once READY has gone out.
//  - A host gets READY at the refresh at which the last group its new frame fed swaps; a new
//    frame that fed no group at all (only SKIPs, or displays the mesh lacks) gets it at the
//    next refresh.
//  - A host waiting for READY holds up a group only if its new frame fed that group, so
//    groups with different members can never wait on each other in a circle.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace l2 {

enum class FrameKind : std::uint8_t { NoSignal, Idle, New, Repeat, Torn, Early };
const char* to_string(FrameKind kind);

// What the sequencer needs to know about one input frame.
struct FrameObservation {
  bool present = false;
  bool idle = true;   // no COPY or SKIP header
  bool torn = false;  // COPY/SKIP headers of both parities
  int parity = 0;
  std::uint64_t groups_fed = 0;  // bit g: a COPY strip reached a display of group g
};

class FrameSequencer {
 public:
  static constexpr int kMaxGroups = 64;

  FrameSequencer(int inputs, int groups);

  struct Refresh {
    std::vector<int> swapped_groups;  // ascending
    std::vector<int> ready_inputs;    // ascending: READY goes to these hosts
  };
  // The output refresh that starts a tick: groups completed during the last tick swap now.
  void refresh(Refresh& out);

  struct Decision {
    std::vector<FrameKind> kinds;       // per input
    std::vector<std::uint8_t> route;    // per input: 1 = write this frame's strips
    std::vector<int> completed_groups;  // ascending: finish their frame, swap at next refresh
  };
  // This tick's frames, one per input (missing entries: no signal).
  void observe(std::span<const FrameObservation> frames, Decision& out);

  int input_count() const { return static_cast<int>(inputs_.size()); }
  int group_count() const { return static_cast<int>(groups_.size()); }
  bool awaiting_ready(int input) const { return inputs_[input].awaiting; }

 private:
  struct InputState {
    int accepted_parity = -1;       // none yet
    bool awaiting = false;          // new frame accepted, READY not sent yet
    std::uint64_t fed = 0;          // groups the accepted new frame fed
    std::uint64_t not_swapped = 0;  // ... of which these have not swapped yet
  };
  struct GroupState {
    bool pending = false;         // some new frame has been written into its back buffers
    bool swap_scheduled = false;  // complete: swaps at the next refresh
  };

  FrameKind classify(int input, const FrameObservation& f) const;
  bool holds_up(int input, const FrameObservation& f, int group) const;

  std::vector<InputState> inputs_;
  std::vector<GroupState> groups_;
};

}  // namespace l2
