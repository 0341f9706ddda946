// Spec §4 rules 1, 2 and 5: place a pipeserver's tiles, in list order, into its framebuffer;
// KEY and DEPTH tiles take a four-column gap and their payload's columns (§7).
#include <fmt/format.h>

#include "strip_headers/strip_header.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

std::string describe(int pipeserver, int index, const DisplayTile& t) {
  const char* kind = t.compositing == Compositing::Key     ? ", KEY"
                     : t.compositing == Compositing::Depth ? ", DEPTH"
                                                           : "";
  return fmt::format("pipeserver {}: tile {} (display {}, {}x{} at {},{}{})", pipeserver, index,
                     t.display, t.on_display.w, t.on_display.h, t.on_display.x, t.on_display.y,
                     kind);
}

// A tile must be expressible in headers: every COPY names display, x, y + r and width in their
// bit widths (spec §2). Checked here so nothing is drawn for a plan that cannot be encoded.
void check_encodable(int pipeserver, int index, const DisplayTile& t) {
  const Rect& r = t.on_display;
  const char* problem = nullptr;
  if (t.display < 0 || t.display >= kMaxDisplays) {
    problem = "display must be 0..63";
  } else if (r.w < 1 || r.h < 1) {
    problem = "tile is empty";
  } else if (r.w > kMaxCoordinate) {
    problem = "width must be at most 4095";
  } else if (r.x < 0 || r.x > kMaxCoordinate || r.y < 0 || r.bottom() - 1 > kMaxCoordinate) {
    problem = "display coordinates must be 0..4095";
  } else if (t.compositing != Compositing::Copy && payload_columns(t) + 2 > kMaxCoordinate) {
    problem = "the SKIP below a KEY or DEPTH tile, payload + 2 wide, must be at most 4095";
  } else if (t.compositing == Compositing::Key && t.key > 0xFFFFFF) {
    problem = "key colour must be 000000..ffffff";
  }
  if (problem) throw LayoutError(fmt::format("{}: {}", describe(pipeserver, index, t), problem));
}

}  // namespace

void place_stamp_strip(PipeserverPlan& plan) {
  for (int i = 0; i < static_cast<int>(plan.rows.size()); ++i) {
    const PackedRow& row = plan.rows[static_cast<std::size_t>(i)];
    const PackedTile& last =
        plan.tiles[static_cast<std::size_t>(row.first_tile + row.tile_count - 1)];
    const int end_x = last.fb_x + payload_columns(last.tile);
    if (plan.fb_width - end_x < kStampStripColumns) continue;
    plan.stamp_row = i;
    plan.stamp_x = end_x + kHeaderPixels;
    return;
  }
}

PipeserverPlan pack_tiles(int pipeserver, int fb_width, int fb_height,
                          const std::vector<DisplayTile>& tiles) {
  if (fb_width < kHeaderPixels + 1 || fb_height < 1) {
    throw LayoutError(fmt::format("pipeserver {}: framebuffer {}x{} is too small", pipeserver,
                                  fb_width, fb_height));
  }
  PipeserverPlan plan;
  plan.pipeserver = pipeserver;
  plan.fb_width = fb_width;
  plan.fb_height = fb_height;
  plan.tiles.reserve(tiles.size());

  int gap_x = 0;  // where the next tile's header gap starts in the current row
  for (int i = 0; i < static_cast<int>(tiles.size()); ++i) {
    const DisplayTile& t = tiles[i];
    check_encodable(pipeserver, i, t);
    const int columns = gap_columns(t) + payload_columns(t);
    if (columns > fb_width) {
      throw LayoutError(fmt::format(
          "{} does not fit the {}x{} framebuffer: needs {} columns, {} too many",
          describe(pipeserver, i, t), fb_width, fb_height, columns, columns - fb_width));
    }
    // Rule 2: a tile whose gap and pixels would pass W starts a new row below the last one.
    if (plan.rows.empty() || gap_x + columns > fb_width) {
      const int y = plan.used_height();
      plan.rows.push_back({y, 0, i, 0});
      gap_x = 0;
    }
    PackedRow& row = plan.rows.back();
    plan.tiles.push_back({t, gap_x + gap_columns(t), row.y});
    row.height = std::max(row.height, t.on_display.h);
    ++row.tile_count;
    gap_x += columns;
  }

  // Rule 5, height: name the first tile that crosses the bottom and what all tiles need.
  const int needed = plan.used_height();
  for (const PackedRow& row : plan.rows) {
    if (row.y + row.height <= fb_height) continue;
    for (int i = row.first_tile; i < row.first_tile + row.tile_count; ++i) {
      const PackedTile& p = plan.tiles[i];
      if (p.fb_y + p.tile.on_display.h <= fb_height) continue;
      throw LayoutError(fmt::format(
          "{} does not fit the {}x{} framebuffer: needs {} rows, {} too many",
          describe(pipeserver, i, p.tile), fb_width, fb_height, needed, needed - fb_height));
    }
  }
  return plan;
}

}  // namespace l2
