// The proof of swap lock: in every refresh, every display of a swap-lock group shows the same
// frame, whichever board column (rank) holds it. Columns record per refresh the frame stamp each
// of their displays shows; this checks one refresh's records.
// Pure logic, so a violation can be fed to it directly.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"
#include "lightning2_emu/swap_group.hpp"

namespace l2 {

class SwapLockCheck {
 public:
  explicit SwapLockCheck(std::vector<SwapGroup> groups) : groups_(std::move(groups)) {}

  // One line naming refresh, group, display and rank when a display of a group shows another
  // frame than the group's first display that shows one; nullopt when the refresh is in lock.
  // Displays without a frame yet are not compared.
  Status check(std::uint64_t refresh, std::span<const DisplayShown> shown) const;

 private:
  std::vector<SwapGroup> groups_;
};

}  // namespace l2
