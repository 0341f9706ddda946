#include "tilelayout/planner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>

#include "tilelayout/coverage.hpp"
#include "tilelayout/dvi_timing.hpp"
#include "tilelayout/fit.hpp"
#include "tilelayout/several_meshes.hpp"

namespace l2 {
namespace {

// A framebuffer row is as tall as its tallest tile, so packing tall tiles together wastes
// least: each pipeserver's list is sorted by height, tallest first, then in tiling order.
std::vector<DisplayTile> packing_order(std::vector<DisplayTile> tiles) {
  std::stable_sort(tiles.begin(), tiles.end(), [](const DisplayTile& a, const DisplayTile& b) {
    return a.on_display.h > b.on_display.h;
  });
  return tiles;
}

std::string where(const Wall& wall, int line) {
  if (wall.source.empty()) return "";
  if (line <= 0) return wall.source.string() + ": ";
  return fmt::format("{}:{}: ", wall.source.string(), line);
}

std::vector<int> pipeserver_of_logical(const Wall& wall, const std::vector<Rect>& logical,
                                       const std::vector<DisplayTile>& tiles,
                                       AssignmentPolicy policy, int pipeserver_count) {
  std::vector<long long> visible(logical.size(), 0);
  for (const DisplayTile& t : tiles) visible[t.logical_tile] += t.on_display.area();
  return assign_pipeservers(policy, logical, visible, pipeserver_count,
                            {0, 0, wall.canvas_width, wall.canvas_height});
}

// Every display tile of the plan (once per layer in a depth wall, the overlay last) and the
// pipeserver that renders it. Empty when the layers cannot share the pipeservers evenly.
struct Distribution {
  std::vector<DisplayTile> tiles;
  std::vector<int> pipeserver;
};

DisplayTile overlay_tile(const Wall& wall, int logical_index) {
  const Overlay& o = *wall.overlay;
  const Display& d = wall.displays[static_cast<std::size_t>(o.display)];
  return {o.display, o.on_display, d.to_canvas(o.on_display), logical_index, Compositing::Key,
          o.key,     d.orientation};
}

// `given`: the pipeserver of each logical tile, chosen by the caller instead of the policy.
Distribution distribute(const Wall& wall, const std::vector<Rect>& logical,
                        const std::vector<DisplayTile>& tiles, AssignmentPolicy policy,
                        int pipeserver_count, const std::vector<int>* given = nullptr) {
  const int sharing = pipeserver_count - (wall.overlay ? 1 : 0);
  const int layers = layer_count(wall, pipeserver_count);
  if (sharing < 1 || layers < 1 || sharing % layers != 0) return {};
  const int per_layer = sharing / layers;
  const std::vector<int> pipeserver_of =
      given ? *given : pipeserver_of_logical(wall, logical, tiles, policy, per_layer);
  Distribution d;
  for (int layer = 0; layer < layers; ++layer) {
    for (DisplayTile t : tiles) {
      if (wall.depth_layers != 0) t.compositing = Compositing::Depth;
      d.tiles.push_back(t);
      d.pipeserver.push_back(layer * per_layer + pipeserver_of[t.logical_tile]);
    }
  }
  if (wall.overlay) {
    d.tiles.push_back(overlay_tile(wall, static_cast<int>(logical.size())));
    d.pipeserver.push_back(sharing);
  }
  return d;
}

// The error with what would fit appended: "...; fits with framebuffer_height = 200 ...".
LayoutError not_fitting(const Wall& wall, int line, const std::string& what) {
  const std::string hint = fit_hint(wall, suggest_fit(wall));
  return LayoutError(where(wall, line) + what + (hint.empty() ? "" : "; " + hint));
}

// Every pipeserver's framebuffer goes out on one DVI link at the wall's refresh rate.
std::optional<std::string> dvi_link_warning(const Wall& wall) {
  const DviTiming t = dvi_timing(wall.framebuffer_width, wall.framebuffer_height, wall.refresh_hz);
  if (t.links() == 1) return std::nullopt;
  return fmt::format(
      "warning: framebuffers of {}x{} at {} Hz need a {:.2f} MHz pixel clock (CVT reduced "
      "blanking), more than single-link DVI carries ({:g} MHz): {}",
      wall.framebuffer_width, wall.framebuffer_height, wall.refresh_hz, t.pixel_clock_mhz,
      kSingleLinkDviMhz,
      t.links() == 2 ? fmt::format("a dual link carries it ({:g} MHz)", kDualLinkDviMhz)
                     : fmt::format("more than a dual link too ({:g} MHz)", kDualLinkDviMhz));
}

}  // namespace

int layer_count(const Wall& wall, int pipeserver_count) {
  if (wall.depth_layers == 0) return 1;
  if (wall.depth_layers != kAllLayers) return wall.depth_layers;
  return pipeserver_count - (wall.overlay ? 1 : 0);
}

namespace {

std::vector<std::vector<DisplayTile>> tile_lists(const Distribution& d, int pipeserver_count) {
  std::vector<std::vector<DisplayTile>> lists(
      static_cast<std::size_t>(std::max(pipeserver_count, 0)));
  for (std::size_t i = 0; i < d.tiles.size(); ++i) lists[d.pipeserver[i]].push_back(d.tiles[i]);
  for (auto& list : lists) list = packing_order(std::move(list));
  return lists;
}

TileLayout plan(const Wall& wall, const std::vector<int>* pipeserver_of_logical,
                const std::vector<int>& gone = {}) {
  if (wall.mesh_count > 1) {
    // A wall of several meshes is planned mesh by mesh; none balances or survives a loss.
    if (pipeserver_of_logical || !gone.empty()) {
      throw LayoutError(where(wall, wall.meshes_line) +
                        fmt::format("a given assignment is for a wall of one mesh; this wall's "
                                    "{} displays need {} meshes",
                                    wall.displays.size(), wall.mesh_count));
    }
    return plan_several_meshes(wall);
  }
  TileLayout layout;
  layout.wall = wall;
  layout.meshes = mesh_parts(wall);
  layout.logical_tiles = make_logical_tiles(wall);
  layout.tiles = split_at_displays(wall, layout.logical_tiles);
  if (pipeserver_of_logical && (wall.depth_layers != 0 || wall.overlay ||
                                pipeserver_of_logical->size() != layout.logical_tiles.size())) {
    throw LayoutError(where(wall, 0) +
                      fmt::format("a given assignment needs a sort-first wall without overlay "
                                  "and one pipeserver for each of its {} logical tiles, got {}",
                                  layout.logical_tiles.size(), pipeserver_of_logical->size()));
  }
  const auto is_gone = [&gone](int s) {
    return std::find(gone.begin(), gone.end(), s) != gone.end();
  };
  for (int s : gone) {
    if (s < 0 || s >= wall.pipeserver_count) {
      throw LayoutError(where(wall, 0) + fmt::format("gone pipeserver {} is not 0..{}", s,
                                                     wall.pipeserver_count - 1));
    }
  }
  if (pipeserver_of_logical) {
    for (std::size_t t = 0; t < pipeserver_of_logical->size(); ++t) {
      const int s = (*pipeserver_of_logical)[t];
      if (s < 0 || s >= wall.pipeserver_count) {
        throw LayoutError(where(wall, 0) + fmt::format("assigned pipeserver {} is not 0..{}", s,
                                                       wall.pipeserver_count - 1));
      }
      if (is_gone(s)) {
        throw LayoutError(where(wall, 0) + fmt::format("pipeserver {} is gone but was given "
                                                       "logical tile {}",
                                                       s, t));
      }
    }
  }

  const Distribution d = distribute(wall, layout.logical_tiles, layout.tiles, wall.assignment,
                                    wall.pipeserver_count, pipeserver_of_logical);
  const std::vector<std::vector<DisplayTile>> lists = tile_lists(d, wall.pipeserver_count);
  if (d.tiles.empty()) {
    throw LayoutError(where(wall, wall.depth_line) +
                      fmt::format("depth.layers: {} layers do not share {} pipeservers evenly",
                                  layer_count(wall, wall.pipeserver_count), wall.pipeserver_count));
  }
  layout.tiles = d.tiles;
  layout.tile_pipeserver = d.pipeserver;
  if (wall.overlay) layout.logical_tiles.push_back(layout.tiles.back().on_canvas);
  const int layers = layer_count(wall, wall.pipeserver_count);
  const int per_layer = (wall.pipeserver_count - (wall.overlay ? 1 : 0)) / layers;
  for (int s = 0; s < wall.pipeserver_count; ++s) {
    try {
      layout.pipeservers.push_back(
          pack_tiles(s, wall.framebuffer_width, wall.framebuffer_height, lists[s]));
      place_stamp_strip(layout.pipeservers.back());
    } catch (const LayoutError& e) {
      throw not_fitting(wall, wall.framebuffer_line, e.what());
    }
    if (s < per_layer * layers && wall.depth_layers != 0) {
      layout.pipeservers.back().layer = s / per_layer;
      layout.pipeservers.back().layers = layers;
    }
  }
  for (const PipeserverPlan& s : layout.pipeservers) {
    // A gone pipeserver scans out nothing at all: it cannot hold up a READY.
    if (!s.tiles.empty() || is_gone(s.pipeserver)) continue;
    throw not_fitting(wall, 0,
                      fmt::format("pipeserver {} gets no tiles ({} display tiles for {} "
                                  "pipeservers); every pipeserver needs a tile (one without "
                                  "scans out idle frames, which never earn READY)",
                                  s.pipeserver, layout.tiles.size(), layout.pipeservers.size()));
  }
  for (const std::string& w : coverage_warnings(wall, display_coverage(wall, layout.tiles))) {
    layout.warnings.push_back(where(wall, 0) + "warning: " + w);
  }
  if (auto w = dvi_link_warning(wall))
    layout.warnings.push_back(where(wall, wall.framebuffer_line) + *w);
  return layout;
}

}  // namespace

std::vector<std::vector<DisplayTile>> pipeserver_tile_lists(const Wall& wall,
                                                            const std::vector<Rect>& logical,
                                                            const std::vector<DisplayTile>& tiles,
                                                            AssignmentPolicy policy,
                                                            int pipeserver_count) {
  return tile_lists(distribute(wall, logical, tiles, policy, pipeserver_count), pipeserver_count);
}

TileLayout plan_layout(const Wall& wall) {
  return plan(wall, nullptr);
}

TileLayout plan_layout(const Wall& wall, const std::vector<int>& pipeserver_of_logical) {
  return plan(wall, &pipeserver_of_logical);
}

TileLayout plan_layout(const Wall& wall, const std::vector<int>& pipeserver_of_logical,
                       const std::vector<int>& gone) {
  return plan(wall, &pipeserver_of_logical, gone);
}

}  // namespace l2
