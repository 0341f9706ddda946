#include "tilelayout/survival.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "packed_rows.hpp"
#include "tilelayout/fit.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

std::vector<long long> visible_area(const Wall& wall, const std::vector<Rect>& logical) {
  std::vector<long long> visible(logical.size(), 0);
  for (const DisplayTile& t : split_at_displays(wall, logical))
    visible[static_cast<std::size_t>(t.logical_tile)] += t.on_display.area();
  return visible;
}

// The policy's own first, then by visible area: fewer framebuffers hold the same pixels, and
// shared out by area they fit more often.
std::vector<AssignmentPolicy> policies_to_try(const Wall& wall) {
  if (wall.assignment == AssignmentPolicy::AreaBalanced) return {wall.assignment};
  return {wall.assignment, AssignmentPolicy::AreaBalanced};
}

std::string plural(int n) {
  return fmt::format("{} pipeserver{}", n, n == 1 ? "" : "s");
}

std::string height_need(const Wall& wall, std::optional<int> height) {
  if (!height) {
    return fmt::format("no framebuffer_height up to {} holds them at framebuffer_width = {}",
                       kMaxFramebufferSide, wall.framebuffer_width);
  }
  const std::string board = *height > wall.board_max_height
                                ? fmt::format(" with [mesh] board_max_height = {}", *height)
                                : std::string();
  return fmt::format("framebuffer_height >= {}{}", *height, board);
}

}  // namespace

namespace {

// When the height a loss needs is past what the boards read: the framebuffer at the boards'
// widest that holds the tiles within their rows, if one does.
std::string within_boards(const Wall& wall, int lost) {
  if (wall.framebuffer_width >= wall.board_max_width) return {};
  Wall wide = wall;
  wide.framebuffer_width = wall.board_max_width;
  const std::optional<int> h = survival_height(wide, lost);
  if (!h || *h > wall.board_max_height) return {};
  return fmt::format(
      "framebuffer_width = {}, framebuffer_height = {}: survives the loss of {} within the "
      "boards' {}x{}",
      wide.framebuffer_width, *h, plural(lost), wall.board_max_width, wall.board_max_height);
}

}  // namespace

std::vector<int> assign_without(const Wall& wall, const std::vector<Rect>& logical,
                                AssignmentPolicy policy, const std::vector<int>& gone) {
  std::vector<int> serving;
  for (int s = 0; s < wall.pipeserver_count; ++s) {
    if (!std::binary_search(gone.begin(), gone.end(), s)) serving.push_back(s);
  }
  std::vector<int> of = assign_pipeservers(policy, logical, visible_area(wall, logical),
                                           static_cast<int>(serving.size()),
                                           {0, 0, wall.canvas_width, wall.canvas_height});
  for (int& s : of) s = serving[static_cast<std::size_t>(s)];
  return of;
}

TileLayout plan_without(const Wall& wall, const std::vector<int>& gone) {
  const std::vector<Rect> logical = make_logical_tiles(wall);
  try {
    return plan_layout(wall, assign_without(wall, logical, wall.assignment, gone), gone);
  } catch (const LayoutError&) {
    if (wall.assignment == AssignmentPolicy::AreaBalanced) throw;
    try {
      return plan_layout(wall, assign_without(wall, logical, AssignmentPolicy::AreaBalanced, gone),
                         gone);
    } catch (const LayoutError&) {
    }
    throw;
  }
}

std::optional<int> survival_height(const Wall& wall, int lost) {
  const int left = wall.pipeserver_count - lost;
  if (lost < 0 || left < 1) return std::nullopt;
  const std::vector<Rect> logical = make_logical_tiles(wall);
  const std::vector<DisplayTile> tiles = split_at_displays(wall, logical);
  std::optional<int> best;
  for (const AssignmentPolicy policy : policies_to_try(wall)) {
    const auto lists = pipeserver_tile_lists(wall, logical, tiles, policy, left);
    const bool idle =
        std::any_of(lists.begin(), lists.end(), [](const auto& l) { return l.empty(); });
    const std::optional<int> rows = tallest(lists, wall.framebuffer_width);
    if (idle || !rows || *rows > kMaxFramebufferSide) continue;
    best = std::min(best.value_or(*rows), std::max(*rows, 1));
  }
  return best;
}

Survival survival(const Wall& wall) {
  Survival s;
  if (wall.depth_layers != 0 || wall.overlay) {
    s.not_offered =
        "a wall with [depth] or [overlay] does not balance, and only a balanced run "
        "survives a loss";
    return s;
  }
  if (wall.pipeserver_count < 2) {
    s.not_offered = "its one pipeserver has nobody to take its tiles";
    return s;
  }
  const int most = wall.pipeserver_count - 1;
  for (int k = 1; k <= most; ++k) {
    const std::optional<int> h = survival_height(wall, k);
    const bool fits = h && *h <= wall.framebuffer_height;
    if (fits && s.survives == k - 1) s.survives = k;
    if (k <= 2 || k == s.survives + 1) s.heights.emplace_back(k, h);
    if (k > 2 && k > s.survives) break;
  }
  return s;
}

std::string survival_line(const Wall& wall, const Survival& s) {
  if (!s.not_offered.empty()) return "survives the loss of no pipeserver: " + s.not_offered;
  const std::string framebuffers =
      fmt::format("framebuffers {}x{}", wall.framebuffer_width, wall.framebuffer_height);
  if (s.survives == wall.pipeserver_count - 1) {
    return fmt::format("survives the loss of any {} of its {} ({})", s.survives,
                       plural(wall.pipeserver_count), framebuffers);
  }
  const int next = s.survives + 1;
  const auto need = std::find_if(s.heights.begin(), s.heights.end(),
                                 [next](const auto& kh) { return kh.first == next; });
  return fmt::format("survives the loss of {} ({}); {}: needs {}",
                     s.survives == 0 ? "no pipeserver" : plural(s.survives), framebuffers, next,
                     height_need(wall, need == s.heights.end() ? std::nullopt : need->second));
}

std::vector<std::string> survival_suggestions(const Wall& wall, const Survival& s) {
  if (!s.not_offered.empty()) return {"survives the loss of no pipeserver: " + s.not_offered};
  std::vector<std::string> lines;
  for (const auto& [k, h] : s.heights) {
    if (k > 2) break;
    if (!h) {
      lines.push_back(fmt::format(
          "no framebuffer_height up to {} at framebuffer_width = {} survives the loss of {}",
          kMaxFramebufferSide, wall.framebuffer_width, plural(k)));
      continue;
    }
    const std::string board = *h > wall.board_max_height
                                  ? fmt::format(", and [mesh] board_max_height = {}", *h)
                                  : std::string();
    lines.push_back(
        fmt::format("framebuffer_height = {} (at framebuffer_width = {}{}): survives "
                    "the loss of {}",
                    *h, wall.framebuffer_width, board, plural(k)));
    if (!board.empty()) {
      if (std::string wider = within_boards(wall, k); !wider.empty()) lines.push_back(wider);
    }
  }
  return lines;
}

}  // namespace l2
