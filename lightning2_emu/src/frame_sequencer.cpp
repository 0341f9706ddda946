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

void FrameSequencer::refresh(Refresh& out) {
  out.swapped_groups.clear();
  out.ready_inputs.clear();
  std::uint64_t swapped = 0;
  for (int g = 0; g < group_count(); ++g) {
    if (!groups_[g].swap_scheduled) continue;
    groups_[g].swap_scheduled = false;
    swapped |= bit(g);
    out.swapped_groups.push_back(g);
  }
  for (int i = 0; i < input_count(); ++i) {
    InputState& in = inputs_[i];
    in.not_swapped &= ~swapped;
    if (in.awaiting && in.not_swapped == 0) {
      in.awaiting = false;
      out.ready_inputs.push_back(i);
    }
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

bool FrameSequencer::holds_up(int input, const FrameObservation& f, int group) const {
  const InputState& in = inputs_[input];
  if (!f.present || f.idle || !(f.groups_fed & bit(group))) return false;
  if (in.not_swapped & bit(group)) return false;  // its new frame is in this group already
  return !in.awaiting || (in.fed & bit(group));
}

void FrameSequencer::observe(std::span<const FrameObservation> frames, Decision& out) {
  const int n = input_count();
  out.kinds.assign(n, FrameKind::NoSignal);
  out.route.assign(n, 0);
  out.completed_groups.clear();
  static const FrameObservation kNoSignal{};
  auto frame = [&](int i) -> const FrameObservation& {
    return i < static_cast<int>(frames.size()) ? frames[i] : kNoSignal;
  };
  for (int i = 0; i < n; ++i) {
    const FrameObservation& f = frame(i);
    const FrameKind kind = classify(i, f);
    out.kinds[i] = kind;
    if (kind != FrameKind::New) continue;
    InputState& in = inputs_[i];
    const std::uint64_t fed = f.groups_fed & (group_count() == 64 ? ~0ull : bit(group_count()) - 1);
    in.accepted_parity = f.parity;
    in.awaiting = true;
    in.fed = fed;
    in.not_swapped = fed;
    out.route[i] = 1;
    for (int g = 0; g < group_count(); ++g) {
      if (fed & bit(g)) groups_[g].pending = true;
    }
  }
  for (int g = 0; g < group_count(); ++g) {
    GroupState& gs = groups_[g];
    if (!gs.pending || gs.swap_scheduled) continue;
    bool held = false;
    for (int i = 0; i < n && !held; ++i) held = holds_up(i, frame(i), g);
    if (held) continue;
    gs.pending = false;
    gs.swap_scheduled = true;
    out.completed_groups.push_back(g);
  }
}

}  // namespace l2
