// Spec §6 as a state machine, pure logic: which input frames are new, repeated, torn or idle,
// which are routed, when a swap-lock group swaps and which hosts get READY. It sees frames only
// through their parsed summaries, so it is tested without any pixels.
//
// A tick is one refresh: refresh() swaps the groups completed during the last tick, then the
// tick's frames are decided on and the decision committed. decide() changes nothing, so a
// caller whose observations turn out wrong (a predicted frame that was not what it was taken
// for, router.hpp) can ask again before it commits.
//
// Decisions the spec leaves open, made here:
//  - An input "feeds" a group when its frame has a COPY, KEY or DEPTH strip that reaches a
//    display of it.
//  - A frame with the accepted parity is a repeat (the host is still waiting for READY, or has
//    not swapped since): it is not routed again and holds up every group it feeds that has not
//    received its new frame.
//  - A new parity from a host that has not had READY yet (it did not wait) is "early": not
//    accepted, not routed; the same frame is accepted once READY has gone out.
//  - A host gets READY in the tick in which the last group its new frame fed completes; a new
//    frame that fed no group at all (only SKIPs, or displays the mesh lacks) gets it in the
//    tick it is accepted. Its groups swap at the next refresh, where the host's next frame, if
//    it swapped one in at READY, is taken in: a host that keeps up gets a new frame on the
//    displays at every refresh, one refresh after it was scanned out.
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
  bool idle = true;   // no COPY, KEY, DEPTH or SKIP header
  bool torn = false;  // headers of both parities
  int parity = 0;
  std::uint64_t groups_fed = 0;  // bit g: a COPY, KEY or DEPTH strip reached a display of group g
};

class FrameSequencer {
 public:
  static constexpr int kMaxGroups = 64;

  FrameSequencer(int inputs, int groups);

  // The output refresh that starts a tick: the groups completed during the last tick swap now
  // (ascending).
  void refresh(std::vector<int>& swapped_groups);

  struct Decision {
    std::vector<FrameKind> kinds;       // per input
    std::vector<std::uint8_t> route;    // per input: 1 = write this frame's strips
    std::vector<int> completed_groups;  // ascending: finish their frame, swap at next refresh
    std::vector<int> ready_inputs;      // ascending: READY goes to these hosts now
  };
  // What this tick's frames, one per input (missing entries: no signal), mean. Changes nothing.
  void decide(std::span<const FrameObservation> frames, Decision& out) const;
  // Takes the decision decide() made on the same frames as this tick's.
  void commit(std::span<const FrameObservation> frames, const Decision& decision);

  int input_count() const { return static_cast<int>(inputs_.size()); }
  int group_count() const { return static_cast<int>(groups_.size()); }
  bool awaiting_ready(int input) const { return inputs_[input].awaiting; }

 private:
  struct InputState {
    int accepted_parity = -1;         // none yet
    bool awaiting = false;            // new frame accepted, READY not sent yet
    std::uint64_t fed = 0;            // groups the accepted new frame fed
    std::uint64_t not_completed = 0;  // ... of which these have not completed yet
  };
  struct GroupState {
    bool pending = false;         // some new frame has been written into its back buffers
    bool swap_scheduled = false;  // complete: swaps at the next refresh
  };

  FrameKind classify(int input, const FrameObservation& f) const;
  bool holds_up(int input, const FrameObservation& f, FrameKind kind, int group) const;
  std::uint64_t groups_of(const FrameObservation& f) const;

  std::vector<InputState> inputs_;
  std::vector<GroupState> groups_;
};

}  // namespace l2
