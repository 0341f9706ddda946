#include "l2wall/active_stereo_check.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {
namespace {

const char* eye_name(int eye) {
  return eye == 0 ? "left" : "right";
}

std::string describe(int eye_frame) {
  if (eye_frame < 0) return "nothing";
  return fmt::format("frame {}'s {} eye", eye_frame / 2, eye_name(eye_frame % 2));
}

}  // namespace

Status ActiveStereoCheck::check(std::uint64_t refresh, std::span<const DisplayShown> shown) {
  if (shown.empty()) return {};
  const int group_frame = shown.front().frame < 0 ? -1 : shown.front().frame / 2;
  for (const DisplayShown& s : shown) {
    if (const Status st = check_display(refresh, s, group_frame); !st.ok()) return st;
  }
  if (first_pair_ < 0 && group_frame >= 0) first_pair_ = static_cast<std::int64_t>(refresh);
  if (refreshes_ < max_rows_) {
    if (group_frame < 0) {
      csv_ += fmt::format("{},none,\n", refresh);
    } else {
      csv_ +=
          fmt::format("{},{},{}\n", refresh, eye_name(static_cast<int>(refresh % 2)), group_frame);
    }
  }
  ++refreshes_;
  return {};
}

Status ActiveStereoCheck::check_display(std::uint64_t refresh, const DisplayShown& s,
                                        int group_frame) {
  const int eye = static_cast<int>(refresh % 2);
  const int frame = s.frame < 0 ? -1 : s.frame / 2;
  Seen& seen = last_[s.display];
  const auto broken = [&](const std::string& why) -> Status {
    return Failure{
        fmt::format("active stereo broken in refresh {} ({} eye): display {} (rank {}) "
                    "shows {}{}",
                    refresh, eye_name(eye), s.display, s.rank, describe(s.frame), why)};
  };
  if (s.frame >= 0 && s.frame % 2 != eye) return broken("");
  if (frame != group_frame)
    return broken(fmt::format(", another display of its swap group {}",
                              group_frame < 0 ? "nothing" : fmt::format("frame {}", group_frame)));
  if (frame < 0 && seen.frame >= 0) return broken(fmt::format(" after frame {}", seen.frame));
  if (eye == 1 && frame != seen.frame)
    return broken(fmt::format(" after {}", describe(seen.frame < 0 ? -1 : 2 * seen.frame)));
  if (frame >= 0 && frame < seen.frame) return broken(fmt::format(" after frame {}", seen.frame));
  if (eye == 0 && frame >= 0) {
    ++seen.pairs;
    seen.repeated += frame == seen.frame;
  }
  seen.frame = frame;
  return {};
}

const ActiveStereoCheck::Seen& ActiveStereoCheck::fewest_new() const {
  static const Seen none;
  if (last_.empty()) return none;
  return std::min_element(last_.begin(), last_.end(),
                          [](const auto& a, const auto& b) {
                            return a.second.pairs - a.second.repeated <
                                   b.second.pairs - b.second.repeated;
                          })
      ->second;
}

std::uint64_t ActiveStereoCheck::pairs_shown() const {
  return fewest_new().pairs;
}
std::uint64_t ActiveStereoCheck::pairs_repeated() const {
  return fewest_new().repeated;
}

}  // namespace l2
