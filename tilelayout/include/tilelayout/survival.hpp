// How many lost pipeservers a wall survives (`l2wall run --survive-host-loss`): the lost ones'
// tiles must go to the others, and the room for them is physics, the others' framebuffers.
// The wall's own tiling is dealt to the pipeservers left as if they were the whole wall, by its
// policy or, when that does not fit, by visible area, and packed as the planner packs: what a
// balanced run falls back on when its own cut does not fit after a loss.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The pipeserver of each logical tile of `logical` (a cut of the wall's canvas) under `policy`
// when the pipeservers in `gone` (ascending) take no part: the others dealt the tiles as if
// they were the whole wall.
std::vector<int> assign_without(const Wall& wall, const std::vector<Rect>& logical,
                                AssignmentPolicy policy, const std::vector<int>& gone);

// The wall's own tiling planned without `gone`: by its policy, else by visible area. Throws the
// policy's LayoutError when neither fits.
TileLayout plan_without(const Wall& wall, const std::vector<int>& gone);

// The smallest framebuffer_height at the wall's framebuffer_width whose framebuffers hold every
// tile when any `lost` pipeservers are gone (every choice packs alike: the framebuffers are the
// same size). None: no height up to 4096 does, or a tile is wider than the framebuffer.
std::optional<int> survival_height(const Wall& wall, int lost);

struct Survival {
  // Why the wall survives no loss whatever its framebuffers (a depth or overlay wall does not
  // balance; one pipeserver has nobody to take its tiles); empty otherwise.
  std::string not_offered;
  int survives = 0;  // k: losing any k pipeservers (and any fewer), the others hold every tile
  // survival_height for k = 1, 2 (as far as the pipeserver count allows) and survives + 1.
  std::vector<std::pair<int, std::optional<int>>> heights;
};

Survival survival(const Wall& wall);

// What `tilelayout` prints with the plan: "survives the loss of 1 pipeserver (framebuffers
// 1024x768); 2: needs framebuffer_height >= 1100".
std::string survival_line(const Wall& wall, const Survival& s);

// What `tilelayout --suggest` adds: the framebuffer_height for k = 1 (and 2).
std::vector<std::string> survival_suggestions(const Wall& wall, const Survival& s);

}  // namespace l2
