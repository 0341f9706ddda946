// The proof of swap lock: in every refresh, every display of a swap-lock group shows the same
// frame, whichever board column (rank) holds it; and on a passive stereo wall both eyes of each
// twin pair show the same frame (tilelayout/wall.hpp's eye_pairs): the two eyes of a frame are
// shown in the same refresh, never one eye's frame beside the other eye's older one. Columns record
// per refresh the frame stamp each of their displays shows; this checks one refresh's records. Pure
// logic, so a violation can be fed to it directly.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"
#include "lightning2_emu/swap_group.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class SwapLockCheck {
 public:
  explicit SwapLockCheck(std::vector<SwapGroup> groups, std::vector<EyePair> eyes = {})
      : groups_(std::move(groups)), eyes_(std::move(eyes)) {}

  // One line naming refresh, group, display and rank when a display of a group shows another
  // frame than the group's first display that shows one; nullopt when the refresh is in lock.
  // Displays without a frame yet are not compared. Then one line naming refresh and both
  // displays when the eyes of a pair differ, one without a frame yet included.
  Status check(std::uint64_t refresh, std::span<const DisplayShown> shown) const;

 private:
  Status check_eyes(std::uint64_t refresh, std::span<const DisplayShown> shown) const;

  std::vector<SwapGroup> groups_;
  std::vector<EyePair> eyes_;
};

}  // namespace l2
