#include "tilelayout/plan_report.hpp"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "command_line/printable.hpp"
#include "tilelayout/blend_map.hpp"
#include "tilelayout/coverage.hpp"
#include "tilelayout/dvi_timing.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

// How a display hangs, when not as it is: " turned 90, flipped horizontal (1080x1920 on the
// canvas)".
std::string mounted(const Display& d) {
  const Orientation& o = d.orientation;
  if (o.identity()) return "";
  std::string out;
  if (o.rotation != 0) out += fmt::format(" turned {}", o.rotation);
  if (o.flip != Flip::None)
    out +=
        fmt::format("{} flipped {}", out.empty() ? "" : ",", kFlipNames[static_cast<int>(o.flip)]);
  return out + fmt::format(" ({}x{} on the canvas)", d.canvas_width(), d.canvas_height());
}

// What a display applies to its pixels where they leave the wall, when anything: "; colour gain
// 1,0.96,0.92 offset 0,0,4" or "; colour lut calibration/panel-3.txt" (as the wall file says).
std::string colour(const Display& d) {
  const ColourMatch& c = d.colour;
  switch (c.kind) {
    case ColourMatch::Kind::Gain:
      return fmt::format("; colour gain {} offset {}", fmt::join(c.gain, ","),
                         fmt::join(c.offset, ","));
    case ColourMatch::Kind::Lut:
      return fmt::format("; colour lut {}", printable(c.lut));
    case ColourMatch::Kind::None:
      break;
  }
  return "";
}

// The display's geometry warp and alpha and beta maps, when it has them: "; warp
// calibration/warp-0.pfm; alpha calibration/alpha-0.png at gamma 2.2; beta ..." (as the wall
// file says; said even when a file works out to no change, so the line matches the file).
std::string warp(const Display& d) {
  std::string out;
  if (!d.warp.empty()) out += fmt::format("; warp {}", printable(d.warp));
  if (!d.alpha.empty()) {
    out += fmt::format("; alpha {}", printable(d.alpha));
    if (d.alpha_gamma != 1.0) out += fmt::format(" at gamma {}", d.alpha_gamma);
  }
  if (!d.beta.empty()) out += fmt::format("; beta {}", printable(d.beta));
  return out;
}

// How a display's pixels are blended with the displays it overlaps, when they are: "; blend gamma
// 2.2 over 64 columns at the right edge" (edges of its canvas rectangle, as it hangs).
std::string blend(const Wall& wall, const Display& d) {
  if (!wall.blend.on) return "";
  const BlendRamps r = blend_ramps(wall, d.id);
  std::vector<std::string> edges;
  const auto edge = [&](int width, const char* unit, const char* side) {
    if (width > 0) edges.push_back(fmt::format("{} {} at the {} edge", width, unit, side));
  };
  edge(r.left, "columns", "left");
  edge(r.right, "columns", "right");
  edge(r.top, "rows", "top");
  edge(r.bottom, "rows", "bottom");
  if (edges.empty()) return "";
  const std::string how =
      wall.blend.gamma == 1.0 ? std::string("linear") : fmt::format("gamma {}", wall.blend.gamma);
  return fmt::format("; blend {} over {}", how, fmt::join(edges, ", "));
}

const char* const kTilingNames[] = {"grid", "list", "kd", "strips"};

const char* link_name(int links) {
  return links == 1 ? "single link" : links == 2 ? "dual link" : "more than dual-link DVI carries";
}

// " (layer 1 of 2)" for a pipeserver of a depth wall, " (overlay)" for the overlay's.
std::string role(const TileLayout& layout, const PipeserverPlan& s) {
  const Wall& w = layout.wall;
  if (w.overlay && s.pipeserver == w.pipeserver_count - 1) return " (overlay)";
  if (w.depth_layers != 0) return fmt::format(" (layer {} of {})", s.layer, s.layers);
  return "";
}

std::string compositing(const DisplayTile& t) {
  if (t.compositing == Compositing::Depth) return "  DEPTH";
  if (t.compositing == Compositing::Key) return fmt::format("  KEY {:06x}", t.key);
  return "";
}

// What the wall composites: "; depth: 2 layers of 2 pipeservers each (hybrid sort-first /
// sort-last)", "; overlay: KEY 000000 on display 0 ...".
std::string compositing_summary(const TileLayout& layout) {
  const Wall& w = layout.wall;
  std::string out;
  if (w.depth_layers != 0) {
    const int layers = layer_count(w, w.pipeserver_count);
    const int per_layer = (w.pipeserver_count - (w.overlay ? 1 : 0)) / layers;
    out += fmt::format("depth: {} layer{} of {} pipeserver{} each ({})\n", layers,
                       layers == 1 ? "" : "s", per_layer, per_layer == 1 ? "" : "s",
                       per_layer == 1 ? "sort-last"
                       : layers == 1  ? "sort-first, by depth"
                                      : "hybrid sort-first/sort-last");
  }
  if (w.overlay) {
    const Overlay& o = *w.overlay;
    out += fmt::format("overlay: display {} {}x{} at {},{}, key colour {:06x}, pipeserver {}\n",
                       o.display, o.on_display.w, o.on_display.h, o.on_display.x, o.on_display.y,
                       o.key, w.pipeserver_count - 1);
  }
  return out;
}

// Where a live run's frame stamp goes (tile_layout.hpp): a mark on a display only without room.
std::string stamp_line(const PipeserverPlan& s) {
  if (s.has_stamp_strip()) {
    return fmt::format("  frame stamp: stamp strip at {},{} (routed to no display)\n", s.stamp_x,
                       s.rows[static_cast<std::size_t>(s.stamp_row)].y);
  }
  if (s.tiles.empty()) return "";
  const DisplayTile& t = s.tiles.front().tile;
  return fmt::format(
      "  frame stamp: no row has {} columns left for a stamp strip, so a live run marks display "
      "{} pixel {},{} (framebuffer_width {} gives it one)\n",
      kStampStripColumns, t.display, t.on_display.x, t.on_display.y,
      s.fb_width + kStampStripColumns);
}

void pipeservers(const TileLayout& layout, std::string& out) {
  const int hz = layout.wall.refresh_hz;
  for (const PipeserverPlan& s : layout.pipeservers) {
    long long used = 0;
    for (const PackedTile& p : s.tiles) used += 1LL * payload_columns(p.tile) * p.tile.on_display.h;
    const double total = double(s.fb_width) * s.fb_height;
    out += fmt::format(
        "pipeserver {}{}: {} tiles in {} row{}, {} of {} rows used, framebuffer use {:.1f}%\n",
        s.pipeserver, role(layout, s), s.tiles.size(), s.rows.size(), s.rows.size() == 1 ? "" : "s",
        s.used_height(), s.fb_height, 100.0 * double(used) / total);
    const DviTiming link = dvi_timing(s.fb_width, s.fb_height, hz);
    out += fmt::format(
        "  DVI link: {}x{} at {} Hz needs a {:.2f} MHz pixel clock (CVT reduced blanking, {}x{} "
        "with blanking): {}\n",
        s.fb_width, s.fb_height, hz, link.pixel_clock_mhz, link.h_total, link.v_total,
        link_name(link.links()));
    out += stamp_line(s);
    // Tiles are numbered in packing order, as packing errors number them.
    for (std::size_t i = 0; i < s.tiles.size(); ++i) {
      const PackedTile& p = s.tiles[i];
      const DisplayTile& t = p.tile;
      out += fmt::format(
          "  tile {:>3}: display {:>2} {:>4}x{:<4} at {:>4},{:<4}  packed at {:>4},{:<4}  "
          "canvas {},{} (logical tile {}){}\n",
          i, t.display, t.on_display.w, t.on_display.h, t.on_display.x, t.on_display.y, p.fb_x,
          p.fb_y, t.on_canvas.x, t.on_canvas.y, t.logical_tile, compositing(t));
    }
  }
}

// Which eye a display shows on a stereo wall: its own (passive), both in turn (active), or both
// at once, one in each half (packed).
std::string eye_of(const Wall& wall, const Display& d) {
  if (d.eye != Eye::None) return fmt::format(", {} eye", kEyeNames[static_cast<int>(d.eye)]);
  if (wall.stereo.mode == StereoMode::Active) return ", both eyes in turn (active stereo)";
  if (wall.stereo.mode == StereoMode::SideBySide)
    return ", left eye in its left half, right eye in its right (side-by-side stereo)";
  if (wall.stereo.mode == StereoMode::TopBottom)
    return ", left eye in its top half, right eye in its bottom (top-bottom stereo)";
  return {};
}

void displays(const TileLayout& layout, std::string& out) {
  for (const DisplayCoverage& c : display_coverage(layout.wall, layout.tiles)) {
    const Display& d = layout.wall.displays[c.display];
    std::set<int> from;
    int count = 0;
    for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
      if (layout.tiles[i].display != d.id) continue;
      from.insert(layout.tile_pipeserver[i]);
      ++count;
    }
    out += fmt::format(
        "display {}: {}x{}{} at canvas {},{}, swap group {}{}: {:.1f}% covered ({} of {} pixels) "
        "by {} tiles from pipeservers {}{}{}{}\n",
        d.id, d.width, d.height, mounted(d), d.canvas_x, d.canvas_y, d.swap_group,
        eye_of(layout.wall, d), 100.0 * double(c.covered) / double(c.pixels), c.covered, c.pixels,
        count, from.empty() ? std::string("none") : fmt::format("{}", fmt::join(from, ",")),
        warp(d), blend(layout.wall, d), colour(d));
  }
}

}  // namespace

std::string format_plan(const TileLayout& layout) {
  const Wall& w = layout.wall;
  std::string out = fmt::format(
      "wall \"{}\" ({}): canvas {}x{}, {} displays, {} tiling: {} logical tiles -> {} display "
      "tiles, {} pipeservers of {}x{}, assignment {}\n",
      printable(w.name),
      w.source.empty() ? std::string("built in code") : printable(w.source.string()),
      w.canvas_width, w.canvas_height, w.displays.size(),
      kTilingNames[static_cast<int>(w.tiling.kind)], layout.logical_tiles.size(),
      layout.tiles.size(), w.pipeserver_count, w.framebuffer_width, w.framebuffer_height,
      to_string(w.assignment));
  out += compositing_summary(layout);
  pipeservers(layout, out);
  displays(layout, out);
  for (const std::string& warning : layout.warnings) out += warning + "\n";
  return out;
}

}  // namespace l2
