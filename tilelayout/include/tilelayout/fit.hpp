// What would make a wall fit when its tiles do not fit the framebuffers (or a pipeserver gets
// none): the nearest framebuffer sizes, the other assignment policies and the pipeserver count
// that work, each changed alone. The planner's errors end with them; `tilelayout --suggest`
// prints them for any wall.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tilelayout/wall.hpp"

namespace l2 {

// The largest framebuffer side a wall file takes.
inline constexpr int kMaxFramebufferSide = 4096;

struct FitSuggestions {
  bool fits = false;  // the wall as written
  // Smallest framebuffer_height at the wall's framebuffer_width that holds every pipeserver's
  // tiles, header gaps included (none: a tile is wider than the framebuffer, or > 4096 rows).
  std::optional<int> height_at_width;
  // Smallest framebuffer_width at the wall's framebuffer_height (none: up to 4096, nothing).
  std::optional<int> width_at_height;
  // The framebuffer of smallest area (width, height) that holds every pipeserver's tiles as
  // assigned: the one to change both sides to when neither alone is enough.
  std::optional<std::pair<int, int>> smallest;
  std::vector<AssignmentPolicy> policies;  // other policies that fit at the wall's size
  std::optional<int> pipeserver_count;     // fewest pipeservers that fit at the wall's size
  // A grid wall: the largest tile (width, height) among the written tile scaled down in eighths,
  // each side alone or both, that fits at the wall's framebuffer and pipeservers.
  std::optional<std::pair<int, int>> grid_tile;
  // A pipeserver gets no tile as written: only pipeserver_count and policies can help then.
  bool idle_pipeserver = false;
};

FitSuggestions suggest_fit(const Wall& wall);

// One clause for an error line: "what would fit, each alone: assignment = "blocks" or
// "area-balanced"; framebuffer_height = 200; framebuffer_width = 404; pipeservers.count = 3",
// best fit first: the change that leaves the wall the fewest framebuffer pixels in all.
// A framebuffer side past the wall's board limit comes with the [mesh] limit it needs too
// ("framebuffer_height = 1080 with [mesh] board_max_height = 1080"). Empty when the wall fits
// or nothing found fits.
std::string fit_hint(const Wall& wall, const FitSuggestions& fit);

// The lines `tilelayout --suggest` prints, one working value each with what it holds to.
std::vector<std::string> suggestion_lines(const Wall& wall, const FitSuggestions& fit);

}  // namespace l2
