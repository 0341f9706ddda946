#include "verify/routing_check.hpp"

#include <algorithm>

#include "found_strips.hpp"
#include "plan_match.hpp"
#include "tilelayout/test_pattern.hpp"

namespace l2 {
namespace {

using verify_detail::FoundStrip;

// Who wrote each pixel of one display last, whether more than one COPY strip did, and the
// depth the composite holds there (spec §7).
struct Ownership {
  std::vector<int> owner;             // index into the strips; -1: none
  std::vector<std::uint8_t> written;  // COPY writes: 0, 1, or 2 for two or more
  std::vector<std::uint32_t> depth;   // far (FFFFFF) until a strip writes
};

constexpr std::uint32_t kFar = 0xFFFFFF;

std::uint32_t rgb_value(Rgb c) {
  return std::uint32_t{c.r} << 16 | std::uint32_t{c.g} << 8 | c.b;
}

// Applies strip pixel `x` (display column) of `s` as §7 says: COPY and KEY (but for its key
// colour) write with depth 0, DEPTH where strictly nearer than what the pixel holds.
void apply(std::span<const RgbImage> frames, const FoundStrip& s, int strip, int x, Ownership& map,
           std::size_t at) {
  const int i = x - s.header.x;
  const RgbImage& frame = frames[s.input];
  std::uint32_t depth = 0;
  if (s.how == Compositing::Key && rgb_value(frame.at(s.source_x + i, s.source_row)) == s.key) {
    return;
  }
  if (s.how == Compositing::Depth) {
    depth = rgb_value(frame.at(s.depth_x + i, s.source_row));
    if (depth >= map.depth[at]) return;
  }
  if (s.how == Compositing::Copy) {
    map.written[at] = static_cast<std::uint8_t>(std::min(map.written[at] + 1, 2));
  }
  map.owner[at] = strip;
  map.depth[at] = depth;
}

// The pixels a tile covers; for a KEY tile those its test pattern does not leave transparent.
std::vector<std::uint8_t> planned_pixels(const TileLayout& layout, const Display& d) {
  std::vector<std::uint8_t> planned(static_cast<std::size_t>(d.width) * d.height, 0);
  for (const DisplayTile& t : layout.tiles) {
    if (t.display != d.id) continue;
    const Rect r = intersect(t.on_display, {0, 0, d.width, d.height});
    for (int y = r.y; y < r.bottom(); ++y) {
      for (int x = r.x; x < r.right(); ++x) {
        if (t.compositing == Compositing::Key && key_test_transparent(x, y)) continue;
        planned[static_cast<std::size_t>(y) * d.width + x] = 1;
      }
    }
  }
  return planned;
}

// Writes every strip into the ownership maps, in priority order; what falls past a display's
// edges becomes a MullionRun, what goes to a display the wall lacks is counted on its input.
std::vector<Ownership> write_strips(const Wall& wall, std::span<const RgbImage> frames,
                                    const std::vector<FoundStrip>& strips, RoutingCheck& check) {
  std::vector<Ownership> maps;
  for (const Display& d : wall.displays) {
    const std::size_t n = static_cast<std::size_t>(d.width) * d.height;
    maps.push_back({std::vector<int>(n, -1), std::vector<std::uint8_t>(n, 0),
                    std::vector<std::uint32_t>(n, kFar)});
  }
  for (std::size_t i = 0; i < strips.size(); ++i) {
    const FoundStrip& s = strips[i];
    const int id = s.header.display;
    if (id >= static_cast<int>(wall.displays.size())) {
      check.inputs[s.input].to_absent_display += s.length;
      continue;
    }
    const Display& d = wall.displays[id];
    const int x0 = s.header.x, y = s.header.y;
    const int x1 = y < d.height ? std::min(x0 + s.length, d.width) : x0;
    for (int x = x0; x < x1; ++x) {
      apply(frames, s, static_cast<int>(i), x, maps[id], static_cast<std::size_t>(y) * d.width + x);
    }
    const int visible = std::max(0, x1 - x0);
    if (visible < s.length) {
      const int start = std::max(x0, y < d.height ? d.width : x0);
      check.mullion_runs.push_back({{id, start, y}, s.length - visible});
      check.displays[id].behind_mullions += s.length - visible;
    }
  }
  return maps;
}

// The colour a display pixel shows: from the router's picture when given, else the source pixel
// of the strip that wrote it last.
Rgb shown_colour(std::span<const RgbImage> frames, const FoundStrip& s, int x, int y,
                 const RgbImage* routed) {
  if (routed != nullptr) return routed->at(x, y);
  return frames[s.input].at(s.source_x + (x - s.header.x), s.source_row);
}

// Where a run of pattern pixels belongs: the first display (its own first, then the wall's in
// order) whose mask decodes the first pixel to a position on it and the second, if any, to the
// next column. None when no display does: the pixels are not the test pattern.
std::optional<DisplayPoint> belongs_at(const Wall& wall, int landed_display, Rgb first,
                                       std::optional<Rgb> second) {
  auto fits = [&](int id) -> std::optional<DisplayPoint> {
    const auto p = test_pattern_position(id, first);
    const Display& d = wall.displays[id];
    if (!p || p->first >= d.width || p->second >= d.height) return std::nullopt;
    if (second && test_pattern_position(id, *second) != std::pair{p->first + 1, p->second}) {
      return std::nullopt;
    }
    return DisplayPoint{id, p->first, p->second};
  };
  if (const auto p = fits(landed_display)) return p;
  for (int id = 0; id < static_cast<int>(wall.displays.size()); ++id) {
    if (id == landed_display) continue;
    if (const auto p = fits(id)) return p;
  }
  return std::nullopt;
}

// Joins `run` to a run of the row above that it continues (same strip columns, next source
// row, next display row, next row of where it belongs); else appends it.
void add_run(std::vector<MisplacedRun>& runs, std::size_t first_of_display,
             const MisplacedRun& run) {
  for (std::size_t i = first_of_display; i < runs.size(); ++i) {
    MisplacedRun& g = runs[i];
    const bool continues =
        g.input == run.input && g.landed.x == run.landed.x && g.width == run.width &&
        g.landed.y + g.rows == run.landed.y && g.source_x == run.source_x &&
        g.source_row + g.rows == run.source_row &&
        g.belongs.has_value() == run.belongs.has_value() &&
        (!g.belongs || (g.belongs->display == run.belongs->display &&
                        g.belongs->x == run.belongs->x && g.belongs->y + g.rows == run.belongs->y));
    if (continues) {
      ++g.rows;
      return;
    }
  }
  runs.push_back(run);
}

void classify_display(const TileLayout& layout, std::span<const RgbImage> frames,
                      const std::vector<FoundStrip>& strips, const Ownership& map,
                      const RgbImage* routed, DisplayCheck& out, std::vector<MisplacedRun>& runs) {
  const Display& d = layout.wall.displays[out.display];
  const std::vector<std::uint8_t> planned = planned_pixels(layout, d);
  out.kinds.assign(planned.size(), PixelKind::Unplanned);
  const std::size_t first_run = runs.size();
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      const std::size_t at = static_cast<std::size_t>(y) * d.width + x;
      out.planned += planned[at];
      if (map.owner[at] < 0) {
        if (planned[at] != 0) {
          out.kinds[at] = PixelKind::Missing;
          ++out.missing;
        }
        continue;
      }
      if (map.written[at] > 1) ++out.written_twice;
      const FoundStrip& s = strips[map.owner[at]];
      const Rgb c = shown_colour(frames, s, x, y, routed);
      if (test_pattern_position(d.id, c) == std::pair{x, y}) {
        out.kinds[at] = map.written[at] > 1 ? PixelKind::Twice : PixelKind::Right;
        ++out.right;
        continue;
      }
      out.kinds[at] = PixelKind::Misplaced;
      ++out.misplaced;
      // A run starts here when the pixel to the left is not the same strip's misplaced pixel.
      if (x > 0 && out.kinds[at - 1] == PixelKind::Misplaced && map.owner[at - 1] == map.owner[at])
        continue;
      int end = x + 1;
      while (end < d.width && map.owner[at + (end - x)] == map.owner[at] &&
             !(test_pattern_position(d.id, shown_colour(frames, s, end, y, routed)) ==
               std::pair{end, y})) {
        ++end;
      }
      MisplacedRun run{s.input, s.source_row, s.source_x + (x - s.header.x),
                       s.value, {d.id, x, y}, end - x,
                       1,       std::nullopt};
      const std::optional<Rgb> second =
          end - x > 1 ? std::optional<Rgb>(shown_colour(frames, s, x + 1, y, routed))
                      : std::nullopt;
      run.belongs = belongs_at(layout.wall, d.id, c, second);
      add_run(runs, first_run, run);
    }
  }
}

}  // namespace

bool RoutingCheck::clean() const {
  return std::all_of(displays.begin(), displays.end(),
                     [](const DisplayCheck& d) { return d.clean(); }) &&
         std::all_of(inputs.begin(), inputs.end(), [](const InputCheck& i) { return i.clean(); }) &&
         !parity_differs;
}

RoutingCheck check_routing(const TileLayout& layout, std::span<const RgbImage> frames,
                           std::span<const RgbImage* const> routed) {
  RoutingCheck check;
  check.planned_inputs = static_cast<int>(layout.pipeservers.size());
  std::vector<FoundStrip> skips;
  const std::vector<FoundStrip> strips = verify_detail::find_strips(frames, check.inputs, &skips);
  verify_detail::match_plans(layout, strips, skips, check.inputs);
  // Spec §6: the frames routed together are one application frame, so one parity.
  int parity = kNoParity;
  for (const InputCheck& i : check.inputs) {
    if (i.parity == kNoParity || i.parity == kMixedParity) continue;
    if (parity != kNoParity && parity != i.parity) check.parity_differs = true;
    parity = i.parity;
  }
  for (const Display& d : layout.wall.displays) {
    DisplayCheck display;
    display.display = d.id;
    display.width = d.width;
    display.height = d.height;
    check.displays.push_back(std::move(display));
  }
  const std::vector<Ownership> maps = write_strips(layout.wall, frames, strips, check);
  for (std::size_t i = 0; i < check.displays.size(); ++i) {
    const RgbImage* picture = i < routed.size() ? routed[i] : nullptr;
    const Display& d = layout.wall.displays[i];
    if (picture != nullptr && (picture->width() != d.width || picture->height() != d.height)) {
      picture = nullptr;  // not this display's picture: judged from the frames alone
    }
    classify_display(layout, frames, strips, maps[i], picture, check.displays[i], check.misplaced);
  }
  return check;
}

}  // namespace l2
