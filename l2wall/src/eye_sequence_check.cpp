#include "l2wall/eye_sequence_check.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {
namespace {

std::string describe(int eye_frame) {
  if (eye_frame < 0) return "no frame";
  return fmt::format("eye frame {} (frame {}'s {} eye)", eye_frame, eye_frame / 2,
                     eye_frame % 2 == 0 ? "left" : "right");
}

}  // namespace

Status EyeSequenceCheck::check(std::uint64_t refresh, std::span<const DisplayShown> shown) {
  for (const DisplayShown& s : shown) {
    Seen& seen = last_[s.display];
    if (s.frame == seen.frame) {
      held_ += s.frame >= 0;
      continue;
    }
    if (s.frame != seen.frame + 1) {
      return Failure{
          fmt::format("active stereo pair broken in refresh {}: display {} (rank {}) "
                      "shows {} after {}",
                      refresh, s.display, s.rank, describe(s.frame), describe(seen.frame))};
    }
    seen.frame = s.frame;
    seen.pairs += s.frame % 2;  // a right eye completes its pair
  }
  return {};
}

int EyeSequenceCheck::pairs() const {
  if (last_.empty()) return 0;
  return std::min_element(
             last_.begin(), last_.end(),
             [](const auto& a, const auto& b) { return a.second.pairs < b.second.pairs; })
      ->second.pairs;
}

}  // namespace l2
