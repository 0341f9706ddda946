#include "tilelayout/fit.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "packed_rows.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

using Lists = std::vector<std::vector<DisplayTile>>;

bool every_pipeserver_has_tiles(const Lists& lists) {
  return std::none_of(lists.begin(), lists.end(), [](const auto& l) { return l.empty(); });
}

bool fits(const Lists& lists, int width, int height) {
  const std::optional<int> h = tallest(lists, width);
  return every_pipeserver_has_tiles(lists) && h && *h <= height;
}

struct Tiles {
  std::vector<Rect> logical;
  std::vector<DisplayTile> on_displays;
};

Lists lists_for(const Wall& wall, const Tiles& t, AssignmentPolicy policy, int pipeservers) {
  return pipeserver_tile_lists(wall, t.logical, t.on_displays, policy, pipeservers);
}

// Every framebuffer width from the widest tile's up to 4096: the first that holds the tiles
// within `height` rows, and the width and height of the smallest area that holds them (the
// narrowest of equal areas).
struct WidthScan {
  std::optional<int> width_at_height;
  std::optional<std::pair<int, int>> smallest;
};

WidthScan scan_widths(const Lists& lists, int height) {
  int widest = 1;
  for (const auto& list : lists) {
    for (const DisplayTile& t : list) widest = std::max(widest, t.on_display.w);
  }
  WidthScan scan;
  long long best = 0;
  for (int w = widest + kHeaderPixels; w <= kMaxFramebufferSide; ++w) {
    const std::optional<int> h = tallest(lists, w);
    if (!h || *h > kMaxFramebufferSide) continue;
    if (!scan.width_at_height && *h <= height) scan.width_at_height = w;
    const int rows = std::max(*h, 1);
    if (!scan.smallest || static_cast<long long>(w) * rows < best) {
      scan.smallest = std::pair{w, rows};
      best = static_cast<long long>(w) * rows;
    }
  }
  return scan;
}

// The written grid tile scaled down in eighths, one side or both; the largest that fits.
std::optional<std::pair<int, int>> fitting_grid_tile(const Wall& wall) {
  if (wall.tiling.kind != TilingKind::Grid) return std::nullopt;
  const int tw = wall.tiling.tile_width, th = wall.tiling.tile_height;
  std::optional<std::pair<int, int>> best;
  for (int kw = 8; kw >= 1; --kw) {
    for (int kh = 8; kh >= 1; --kh) {
      const int w = tw * kw / 8, h = th * kh / 8;
      if (w < 1 || h < 1 || (kw == 8 && kh == 8)) continue;
      if (best &&
          static_cast<long long>(w) * h <= static_cast<long long>(best->first) * best->second)
        continue;
      Wall candidate = wall;
      candidate.tiling.tile_width = w;
      candidate.tiling.tile_height = h;
      Tiles t;
      t.logical = make_logical_tiles(candidate);
      t.on_displays = split_at_displays(candidate, t.logical);
      const Lists lists = lists_for(candidate, t, candidate.assignment, candidate.pipeserver_count);
      if (fits(lists, wall.framebuffer_width, wall.framebuffer_height)) best = std::pair{w, h};
    }
  }
  return best;
}

// ", with [mesh] board_max_height = 1080" when a framebuffer side passes the board's limit: a
// framebuffer is one board input, so the limit must grow with it.
std::string board_clause(int value, int board, const char* key) {
  return value > board ? fmt::format(" with [mesh] {} = {}", key, value) : std::string();
}

std::string quoted_policies(const std::vector<AssignmentPolicy>& policies) {
  std::vector<std::string> names;
  for (AssignmentPolicy p : policies) names.push_back(fmt::format("\"{}\"", to_string(p)));
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return out;
}

// The framebuffer pixels a wall has in all: the same tiles fill fewer of them better, so a change
// that adds fewer fits better (a policy or a smaller tile at the written size adds none).
double framebuffer_pixels(const Wall& wall) {
  return double(wall.pipeserver_count) * wall.framebuffer_width * wall.framebuffer_height;
}

}  // namespace

FitSuggestions suggest_fit(const Wall& wall) {
  Tiles t;
  t.logical = make_logical_tiles(wall);
  t.on_displays = split_at_displays(wall, t.logical);
  const int w = wall.framebuffer_width, h = wall.framebuffer_height;
  const Lists lists = lists_for(wall, t, wall.assignment, wall.pipeserver_count);

  FitSuggestions fit;
  fit.fits = fits(lists, w, h);
  fit.idle_pipeserver = !every_pipeserver_has_tiles(lists);
  if (!fit.idle_pipeserver) {
    const std::optional<int> rows = tallest(lists, w);
    if (rows && *rows <= kMaxFramebufferSide) fit.height_at_width = std::max(*rows, 1);
    const WidthScan scan = scan_widths(lists, h);
    fit.width_at_height = scan.width_at_height;
    fit.smallest = scan.smallest;
  }
  if (!fit.fits) fit.grid_tile = fitting_grid_tile(wall);
  for (int p = 0; p <= static_cast<int>(AssignmentPolicy::AreaBalanced); ++p) {
    const auto policy = static_cast<AssignmentPolicy>(p);
    if (policy == wall.assignment) continue;
    if (fits(lists_for(wall, t, policy, wall.pipeserver_count), w, h))
      fit.policies.push_back(policy);
  }
  // Past one pipeserver per display tile and layer (and the overlay's), more only idle.
  const int per_tile = wall.depth_layers > 0 ? wall.depth_layers : 1;
  const int most = std::min<int>(
      kMaxPipeservers, static_cast<int>(t.logical.size()) * per_tile + (wall.overlay ? 1 : 0));
  for (int n = 1; n <= most; ++n) {
    if (fits(lists_for(wall, t, wall.assignment, n), w, h)) {
      fit.pipeserver_count = n;
      break;
    }
  }
  return fit;
}

std::string fit_hint(const Wall& wall, const FitSuggestions& fit) {
  if (fit.fits) return "";
  // Each change with the wall it makes, to order them by how well they fit.
  std::vector<std::pair<std::string, Wall>> parts;
  const auto changed = [&](auto change) {
    Wall w = wall;
    change(w);
    return w;
  };
  if (fit.height_at_width) {
    parts.emplace_back(
        fmt::format("framebuffer_height = {}{}", *fit.height_at_width,
                    board_clause(*fit.height_at_width, wall.board_max_height, "board_max_height")),
        changed([&](Wall& w) { w.framebuffer_height = *fit.height_at_width; }));
  }
  if (fit.width_at_height) {
    parts.emplace_back(
        fmt::format("framebuffer_width = {}{}", *fit.width_at_height,
                    board_clause(*fit.width_at_height, wall.board_max_width, "board_max_width")),
        changed([&](Wall& w) { w.framebuffer_width = *fit.width_at_height; }));
  }
  if (!fit.height_at_width && !fit.width_at_height && fit.smallest) {
    const auto [w, h] = *fit.smallest;
    std::string boards = board_clause(w, wall.board_max_width, "board_max_width");
    const std::string high = board_clause(h, wall.board_max_height, "board_max_height");
    boards += boards.empty() || high.empty() ? high : " and" + high.substr(5);
    parts.emplace_back(
        fmt::format("framebuffer_width = {} with framebuffer_height = {}{}", w, h, boards),
        changed([&](Wall& x) {
          x.framebuffer_width = fit.smallest->first;
          x.framebuffer_height = fit.smallest->second;
        }));
  }
  if (fit.grid_tile) {
    parts.emplace_back(fmt::format("[tiling] tile_width = {} with tile_height = {}",
                                   fit.grid_tile->first, fit.grid_tile->second),
                       changed([&](Wall& w) {
                         w.tiling.tile_width = fit.grid_tile->first;
                         w.tiling.tile_height = fit.grid_tile->second;
                       }));
  }
  if (!fit.policies.empty()) {
    parts.emplace_back("assignment = " + quoted_policies(fit.policies),
                       changed([&](Wall& w) { w.assignment = fit.policies.front(); }));
  }
  if (fit.pipeserver_count) {
    parts.emplace_back(fmt::format("pipeservers.count = {}", *fit.pipeserver_count),
                       changed([&](Wall& w) { w.pipeserver_count = *fit.pipeserver_count; }));
  }
  if (parts.empty()) return "";
  // Best fit first: the change whose framebuffers the tiles fill most (more pipeservers or
  // larger framebuffers than needed leave them emptier); ties as listed above.
  std::vector<std::size_t> order(parts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return framebuffer_pixels(parts[a].second) < framebuffer_pixels(parts[b].second);
  });
  std::string out = "what would fit, each alone: ";
  for (std::size_t i = 0; i < order.size(); ++i)
    out += (i == 0 ? "" : "; ") + parts[order[i]].first;
  return out;
}

std::vector<std::string> suggestion_lines(const Wall& wall, const FitSuggestions& fit) {
  const int w = wall.framebuffer_width, h = wall.framebuffer_height;
  const std::string pipeservers =
      fmt::format("{} pipeserver{}", wall.pipeserver_count, wall.pipeserver_count == 1 ? "" : "s");
  const std::string as_written =
      fmt::format("{}x{}, {}, {}", w, h, pipeservers, to_string(wall.assignment));
  std::vector<std::string> lines;
  lines.push_back(
      fmt::format("as written ({}): {}", as_written, fit.fits ? "fits" : "does not fit"));
  // A framebuffer is one board input: past the board limit the limit must grow with it.
  auto board_note = [&](int value, int board, const char* key) {
    return value > board ? fmt::format(", and [mesh] {} = {}, now {}", key, value, board)
                         : std::string();
  };
  if (fit.height_at_width) {
    lines.push_back(fmt::format(
        "framebuffer_height = {} (at framebuffer_width = {}{})", *fit.height_at_width, w,
        board_note(*fit.height_at_width, wall.board_max_height, "board_max_height")));
  }
  if (fit.width_at_height) {
    lines.push_back(
        fmt::format("framebuffer_width = {} (at framebuffer_height = {}{})", *fit.width_at_height,
                    h, board_note(*fit.width_at_height, wall.board_max_width, "board_max_width")));
  }
  if (fit.smallest) {
    const auto [sw, sh] = *fit.smallest;
    lines.push_back(
        fmt::format("framebuffer_width = {}, framebuffer_height = {}: the smallest framebuffer{}{}",
                    sw, sh, board_note(sw, wall.board_max_width, "board_max_width"),
                    board_note(sh, wall.board_max_height, "board_max_height")));
  }
  if (fit.grid_tile) {
    lines.push_back(
        fmt::format("[tiling] tile_width = {}, tile_height = {} (at {}x{}, {}, {}): "
                    "the largest grid tile that fits",
                    fit.grid_tile->first, fit.grid_tile->second, w, h, pipeservers,
                    to_string(wall.assignment)));
  }
  for (AssignmentPolicy p : fit.policies) {
    lines.push_back(
        fmt::format("assignment = \"{}\" (at {}x{}, {})", to_string(p), w, h, pipeservers));
  }
  if (fit.pipeserver_count) {
    lines.push_back(fmt::format("pipeservers.count = {} (at {}x{}, {}): the fewest that fit",
                                *fit.pipeserver_count, w, h, to_string(wall.assignment)));
  }
  if (lines.size() == 1) lines.push_back("no single change of these values fits");
  return lines;
}

}  // namespace l2
