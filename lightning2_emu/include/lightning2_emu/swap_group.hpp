// Swap-lock groups (spec §6): displays whose back buffers swap together.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lightning2_emu/display_buffers.hpp"

namespace l2 {

struct SwapGroup {
  int id = 0;                 // the swap_group number the displays were configured with
  std::vector<int> displays;  // display ids, ascending
  std::uint64_t swaps = 0;    // swaps so far
};

// One group per distinct DisplaySpec::swap_group, ascending by id. Throws MeshError for more
// than 64 groups.
std::vector<SwapGroup> make_swap_groups(std::span<const DisplaySpec> displays);

}  // namespace l2
