#include "tilelayout/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "image/label_text.hpp"
#include "image/legend.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {
namespace {

constexpr Rgb kUnused{40, 40, 40};
constexpr Rgb kGap{255, 255, 255};
constexpr Rgb kOutline{20, 20, 20};
constexpr Rgb kLabel{0, 0, 0};

void outline(RgbImage& img, const Rect& r, Rgb c, int thickness) {
  img.fill_rect(r.x, r.y, r.w, thickness, c);
  img.fill_rect(r.x, r.bottom() - thickness, r.w, thickness, c);
  img.fill_rect(r.x, r.y, thickness, r.h, c);
  img.fill_rect(r.right() - thickness, r.y, thickness, r.h, c);
}

// A label centred in `r`, as large as fits a quarter of its height: `text`, or `fallback`
// where it does not fit; none if neither does.
void label(RgbImage& img, const Rect& r, const std::string& text, const std::string& fallback) {
  for (const std::string& t : {text, fallback}) {
    int scale = std::max(1, std::min(r.h / 4 / kTextHeight, 12));
    while (scale > 1 && text_width(t, scale) > r.w - 4) --scale;
    const int w = text_width(t, scale), h = kTextHeight * scale;
    if (w > r.w - 2 || h > r.h - 2) continue;
    draw_text(img, r.x + (r.w - w) / 2, r.y + (r.h - h) / 2, t, kLabel, scale);
    return;
  }
}

// Header gaps are two columns: at least that, wider on large framebuffers so they still show
// when the picture is viewed scaled down (drawn over the first columns of the tile).
int gap_width(const PipeserverPlan& plan) {
  return std::max(2, std::max(plan.fb_width, plan.fb_height) / 256);
}

Rgb darker(Rgb c) {
  return {static_cast<std::uint8_t>(c.r / 2), static_cast<std::uint8_t>(c.g / 2),
          static_cast<std::uint8_t>(c.b / 2)};
}

int wall_scale(const Wall& wall) {
  return std::max(1, (std::max(wall.canvas_width, wall.canvas_height) + 4095) / 4096);
}

// `r` on a canvas drawn at 1/`scale`.
Rect shrunk(const Rect& r, int scale) {
  const int x0 = r.x / scale, y0 = r.y / scale;
  return Rect{x0, y0, (r.right() + scale - 1) / scale - x0, (r.bottom() + scale - 1) / scale - y0};
}

}  // namespace

Rgb palette_colour(int i) {
  // Hues spread by the golden angle, light enough for black labels to read on.
  const double h = std::fmod(i * 137.508, 360.0) / 60.0;
  const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = 1, g = x;
      break;
    case 1:
      r = x, g = 1;
      break;
    case 2:
      g = 1, b = x;
      break;
    case 3:
      g = x, b = 1;
      break;
    case 4:
      r = x, b = 1;
      break;
    default:
      r = 1, b = x;
      break;
  }
  const auto channel = [](double v) { return static_cast<std::uint8_t>(110 + v * 145); };
  return {channel(r), channel(g), channel(b)};
}

RgbImage framebuffer_picture(const PipeserverPlan& plan) {
  RgbImage img(plan.fb_width, plan.fb_height, kUnused);
  for (const PackedTile& p : plan.tiles) {
    const Rect r{p.fb_x, p.fb_y, p.tile.on_display.w, p.tile.on_display.h};
    img.fill_rect(r.x, r.y, r.w, r.h, palette_colour(p.tile.display));
    if (r.w > 8 && r.h > 8) outline(img, r, kOutline, 1);
    const char* kind = p.tile.compositing == Compositing::Key ? " KEY" : "";
    label(img, r, fmt::format("D{} L{}{}", p.tile.display, p.tile.logical_tile, kind),
          std::to_string(p.tile.display));
    if (p.tile.compositing != Compositing::Depth) continue;
    // The depth pixels after the colour ones, in a darker shade of the display's colour.
    const Rect z{r.right(), r.y, r.w, r.h};
    img.fill_rect(z.x, z.y, z.w, z.h, darker(palette_colour(p.tile.display)));
    if (z.w > 8 && z.h > 8) outline(img, z, kOutline, 1);
    label(img, z, fmt::format("D{} L{} depth", p.tile.display, p.tile.logical_tile), "z");
  }
  // Drawn over the tiles' first columns where a gap is drawn wider than it is, so that it shows
  // when the picture is scaled down.
  const int drawn = gap_width(plan);
  for (const PackedRow& row : plan.rows) {
    for (int i = row.first_tile; i < row.first_tile + row.tile_count; ++i) {
      const int gap = gap_columns(plan.tiles[i].tile);
      img.fill_rect(plan.tiles[i].fb_x - gap, row.y, std::max(gap, drawn), row.height, kGap);
    }
  }
  return img;
}

RgbImage framebuffer_page(const PipeserverPlan& plan) {
  const int gap = gap_width(plan);
  const bool keyed_or_depth = std::any_of(plan.tiles.begin(), plan.tiles.end(), [](const auto& p) {
    return p.tile.compositing != Compositing::Copy;
  });
  std::vector<LegendEntry> legend{
      {fmt::format(
           "header gap: the 2 columns before every tile{}{}",
           keyed_or_depth ? " (4: header and extension word before KEY and DEPTH tiles)" : "",
           gap == 2 ? std::string() : fmt::format(" (drawn {} wide)", gap)),
       kGap},
      {"unused (black when scanned out)", kUnused}};
  std::set<int> displays;
  for (const PackedTile& p : plan.tiles) displays.insert(p.tile.display);
  for (int d : displays)
    legend.push_back({fmt::format("tiles for display {}", d), palette_colour(d)});
  legend.push_back(
      {"labels: D display the tile goes to, L logical tile (tilelayout lists them)", {}, false});
  return with_legend(framebuffer_picture(plan), legend);
}

RgbImage wall_picture(const TileLayout& layout, int layer) {
  const Wall& wall = layout.wall;
  // Large canvases are drawn smaller, by a whole factor, so the picture stays at most 4096
  // pixels on its longer side.
  const int scale = wall_scale(wall);
  const auto shrink = [scale](const Rect& r) { return shrunk(r, scale); };
  RgbImage img((wall.canvas_width + scale - 1) / scale, (wall.canvas_height + scale - 1) / scale,
               kUnused);
  // A layer's tiles, and the overlay over every layer.
  const auto shown = [&](std::size_t i) {
    return layout.tiles[i].compositing != Compositing::Depth ||
           layout.pipeservers[static_cast<std::size_t>(layout.tile_pipeserver[i])].layer == layer;
  };
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    if (!shown(i)) continue;
    const Rect r = shrink(layout.tiles[i].on_canvas);
    img.fill_rect(r.x, r.y, r.w, r.h, palette_colour(layout.tile_pipeserver[i]));
  }
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    if (!shown(i)) continue;
    const Rect r = shrink(layout.tiles[i].on_canvas);
    if (r.w > 8 && r.h > 8) outline(img, r, kOutline, 1);
    label(img, r, fmt::format("P{} L{}", layout.tile_pipeserver[i], layout.tiles[i].logical_tile),
          std::to_string(layout.tile_pipeserver[i]));
  }
  for (const Display& d : wall.displays) outline(img, shrink(d.on_canvas()), {255, 255, 255}, 2);
  return img;
}

RgbImage meshes_page(const Wall& wall) {
  const int scale = wall_scale(wall);
  RgbImage img((wall.canvas_width + scale - 1) / scale, (wall.canvas_height + scale - 1) / scale,
               kUnused);
  for (const Display& d : wall.displays) {
    const Rect r = shrunk(d.on_canvas(), scale);
    img.fill_rect(r.x, r.y, r.w, r.h, palette_colour(d.mesh));
    if (r.w > 8 && r.h > 8) outline(img, r, kOutline, 1);
    label(img, r, fmt::format("M{} D{}", d.mesh, d.id), fmt::format("M{}", d.mesh));
  }
  std::vector<LegendEntry> legend;
  for (const MeshPart& m : mesh_parts(wall)) {
    legend.push_back({fmt::format("displays mesh {} drives ({} displays; pipeservers {}-{} feed "
                                  "it)",
                                  m.mesh, m.displays.size(), m.first_pipeserver,
                                  m.first_pipeserver + m.pipeserver_count - 1),
                      palette_colour(m.mesh)});
  }
  legend.push_back({"mullions: canvas no display shows", kUnused});
  legend.push_back({"labels: M mesh, D display (its number in the wall)", {}, false});
  if (scale > 1) legend.push_back({fmt::format("drawn at 1/{} size", scale), {}, false});
  return with_legend(img, legend);
}

int wall_layers(const TileLayout& layout) {
  int layers = 1;
  for (const PipeserverPlan& s : layout.pipeservers) layers = std::max(layers, s.layers);
  return layers;
}

RgbImage wall_page(const TileLayout& layout, int layer) {
  std::vector<LegendEntry> legend;
  const int layers = wall_layers(layout);
  for (std::size_t i = 0; i < layout.pipeservers.size(); ++i) {
    const PipeserverPlan& s = layout.pipeservers[i];
    const bool keyed = layout.wall.overlay && s.pipeserver == layout.wall.pipeserver_count - 1;
    if (layers > 1 && !keyed && s.layer != layer) continue;
    legend.push_back({fmt::format("tiles pipeserver {} renders{}", s.pipeserver,
                                  keyed ? " (the overlay, KEY over every layer)" : ""),
                      palette_colour(s.pipeserver)});
  }
  if (layers > 1) {
    legend.push_back({fmt::format("depth layer {} of {}: share {} of the geometry of the "
                                  "scene (the other layers: wall-layer-N.png)",
                                  layer, layers, layer),
                      {},
                      false});
  }
  legend.push_back({"mullions: canvas no display shows", kUnused});
  legend.push_back({"display edges", {255, 255, 255}});
  legend.push_back({"labels: P pipeserver, L logical tile (tilelayout lists them)", {}, false});
  const int scale = wall_scale(layout.wall);
  if (scale > 1) legend.push_back({fmt::format("drawn at 1/{} size", scale), {}, false});
  return with_legend(wall_picture(layout, layer), legend);
}

}  // namespace l2
