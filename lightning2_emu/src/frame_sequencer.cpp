#include "lightning2_emu/frame_sequencer.hpp"

#include <fmt/format.h>

#include "lightning2_emu/mesh.hpp"

namespace l2 {
namespace {
std::uint64_t bit(int g) {
  return std::uint64_t{1} << g;
}
}  // namespace

const char* to_string(FrameKind kind) {
  switch (kind) {
    case FrameKind::NoSignal:
      return "no-signal";
    case FrameKind::Idle:
      return "idle";
    case FrameKind::New:
      return "new";
    case FrameKind::Repeat:
      return "repeat";
    case FrameKind::Torn:
      return "torn";
    case FrameKind::Early:
      return "early";
  }
  return "?";
}

FrameSequencer::FrameSequencer(int inputs, int groups) : inputs_(inputs), groups_(groups) {
  if (groups < 0 || groups > kMaxGroups) {
    throw MeshError(fmt::format("{} swap-lock groups: at most {}", groups, kMaxGroups));
  }
}

void FrameSequencer::refresh(std::vector<int>& swapped_groups) {
  swapped_groups.clear();
  for (int g = 0; g < group_count(); ++g) {
    if (!groups_[g].swap_scheduled) continue;
    groups_[g].swap_scheduled = false;
    swapped_groups.push_back(g);
  }
}

FrameKind FrameSequencer::classify(int input, const FrameObservation& f) const {
  if (!f.present) return FrameKind::NoSignal;
  if (f.idle) return FrameKind::Idle;
  if (f.torn) return FrameKind::Torn;
  const InputState& in = inputs_[input];
  if (f.parity == in.accepted_parity) return FrameKind::Repeat;
  return in.awaiting ? FrameKind::Early : FrameKind::New;
}

std::uint64_t FrameSequencer::groups_of(const FrameObservation& f) const {
  return f.groups_fed & (group_count() == 64 ? ~0ull : bit(group_count()) - 1);
}

// A new frame has delivered to every group it feeds. Any other frame holds up a group it feeds
// unless the input's accepted frame is in that group's back buffers already, or the host waits
// for READY on account of other groups only.
bool FrameSequencer::holds_up(int input, const FrameObservation& f, FrameKind kind,
                              int group) const {
  if (kind == FrameKind::New) return false;
  const InputState& in = inputs_[input];
  if (!f.present || f.idle || !(f.groups_fed & bit(group))) return false;
  if (in.not_completed & bit(group)) return false;
  return !in.awaiting || (in.fed & bit(group));
}

void FrameSequencer::decide(std::span<const FrameObservation> frames, Decision& out) const {
  const int n = input_count();
  static const FrameObservation kNoSignal{};
  auto frame = [&](int i) -> const FrameObservation& {
    return i < static_cast<int>(frames.size()) ? frames[i] : kNoSignal;
  };
  out.kinds.assign(n, FrameKind::NoSignal);
  out.route.assign(n, 0);
  out.completed_groups.clear();
  out.ready_inputs.clear();
  for (int i = 0; i < n; ++i) {
    out.kinds[i] = classify(i, frame(i));
    out.route[i] = out.kinds[i] == FrameKind::New;
  }
  std::uint64_t completed = 0;
  for (int g = 0; g < group_count(); ++g) {
    if (groups_[g].swap_scheduled) continue;
    bool pending = groups_[g].pending;
    for (int i = 0; i < n && !pending; ++i)
      pending = out.route[i] && (frame(i).groups_fed & bit(g));
    if (!pending) continue;
    bool held = false;
    for (int i = 0; i < n && !held; ++i) held = holds_up(i, frame(i), out.kinds[i], g);
    if (held) continue;
    completed |= bit(g);
    out.completed_groups.push_back(g);
  }
  for (int i = 0; i < n; ++i) {
    const InputState& in = inputs_[i];
    const bool accepted = out.route[i] != 0;
    const std::uint64_t waiting_on = accepted ? groups_of(frame(i)) : in.not_completed;
    if ((in.awaiting || accepted) && (waiting_on & ~completed) == 0) out.ready_inputs.push_back(i);
  }
}

void FrameSequencer::commit(std::span<const FrameObservation> frames, const Decision& decision) {
  for (int i = 0; i < input_count() && i < static_cast<int>(frames.size()); ++i) {
    if (!decision.route[i]) continue;
    InputState& in = inputs_[i];
    in.accepted_parity = frames[i].parity;
    in.awaiting = true;
    in.fed = groups_of(frames[i]);
    in.not_completed = in.fed;
    for (int g = 0; g < group_count(); ++g) {
      if (in.fed & bit(g)) groups_[g].pending = true;
    }
  }
  std::uint64_t completed = 0;
  for (const int g : decision.completed_groups) {
    groups_[g].pending = false;
    groups_[g].swap_scheduled = true;
    completed |= bit(g);
  }
  for (InputState& in : inputs_) in.not_completed &= ~completed;
  for (const int i : decision.ready_inputs) inputs_[i].awaiting = false;
}

}  // namespace l2
