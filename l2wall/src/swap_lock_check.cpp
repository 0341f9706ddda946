#include "l2wall/swap_lock_check.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {

namespace {

// What display `id` shows this refresh; null when no column answered for it.
const DisplayShown* shown_by(std::span<const DisplayShown> shown, int id) {
  const auto it = std::find_if(shown.begin(), shown.end(),
                               [id](const DisplayShown& s) { return s.display == id; });
  return it == shown.end() ? nullptr : &*it;
}

}  // namespace

Status SwapLockCheck::check_eyes(std::uint64_t refresh, std::span<const DisplayShown> shown) const {
  for (const EyePair& p : eyes_) {
    const DisplayShown* left = shown_by(shown, p.left);
    const DisplayShown* right = shown_by(shown, p.right);
    if (!left || !right || left->frame == right->frame) continue;
    return Failure{fmt::format(
        "stereo pair broken in refresh {}: left eye display {} (rank {}) shows frame {}, right "
        "eye display {} (rank {}) frame {}",
        refresh, left->display, left->rank, left->frame, right->display, right->rank,
        right->frame)};
  }
  return {};
}

Status SwapLockCheck::check(std::uint64_t refresh, std::span<const DisplayShown> shown) const {
  for (const SwapGroup& g : groups_) {
    const DisplayShown* first = nullptr;
    for (const int id : g.displays) {
      const auto it = std::find_if(shown.begin(), shown.end(),
                                   [id](const DisplayShown& s) { return s.display == id; });
      if (it == shown.end() || it->frame < 0) continue;
      if (!first) {
        first = &*it;
      } else if (it->frame != first->frame) {
        return Failure{fmt::format(
            "swap lock broken in refresh {}: group {}: display {} (rank {}) shows frame {}, "
            "display {} (rank {}) frame {}",
            refresh, g.id, it->display, it->rank, it->frame, first->display, first->rank,
            first->frame)};
      }
    }
  }
  return check_eyes(refresh, shown);
}

}  // namespace l2
