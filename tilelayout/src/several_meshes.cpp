#include "tilelayout/several_meshes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <numeric>

#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

// Twice a display's centre on the canvas, so that it stays in integers.
long long centre2(const Display& d, bool across) {
  const Rect r = d.on_canvas();
  return across ? 2LL * r.x + r.w : 2LL * r.y + r.h;
}

// Gives `ids` (indices into `displays`) meshes first.. first+meshes-1.
void split(const std::vector<Display>& displays, std::vector<int> ids, int meshes, int first,
           std::vector<int>& mesh_of) {
  if (meshes == 1) {
    for (int id : ids) mesh_of[static_cast<std::size_t>(id)] = first;
    return;
  }
  long long x0 = LLONG_MAX, x1 = LLONG_MIN, y0 = LLONG_MAX, y1 = LLONG_MIN;
  for (int id : ids) {
    const Display& d = displays[static_cast<std::size_t>(id)];
    x0 = std::min(x0, centre2(d, true));
    x1 = std::max(x1, centre2(d, true));
    y0 = std::min(y0, centre2(d, false));
    y1 = std::max(y1, centre2(d, false));
  }
  const bool across = x1 - x0 >= y1 - y0;
  // Along the longer side, then the other, then by id: the same cut on every machine.
  std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) {
    const Display& da = displays[static_cast<std::size_t>(a)];
    const Display& db = displays[static_cast<std::size_t>(b)];
    const auto key = [&](const Display& d) {
      return std::pair{centre2(d, across), centre2(d, !across)};
    };
    return key(da) < key(db);
  });
  const int n = static_cast<int>(ids.size());
  const int first_meshes = meshes / 2;
  // In proportion to the meshes, but no side more than its meshes take.
  const int lo = std::max(1, n - kMaxDisplays * (meshes - first_meshes));
  const int hi = std::min(n - 1, kMaxDisplays * first_meshes);
  int cut = std::clamp(static_cast<int>((1LL * n * first_meshes + meshes / 2) / meshes), lo, hi);
  // Rather between two columns (rows) of displays than through one: the nearest cut where the
  // centres move along the cutting side, if the limits allow one.
  const auto between = [&](int i) {
    return centre2(displays[static_cast<std::size_t>(ids[i - 1])], across) !=
           centre2(displays[static_cast<std::size_t>(ids[i])], across);
  };
  for (int step = 0; step <= n; ++step) {
    if (cut - step >= lo && between(cut - step)) {
      cut -= step;
      break;
    }
    if (cut + step <= hi && between(cut + step)) {
      cut += step;
      break;
    }
  }
  split(displays, {ids.begin(), ids.begin() + cut}, first_meshes, first, mesh_of);
  split(displays, {ids.begin() + cut, ids.end()}, meshes - first_meshes, first + first_meshes,
        mesh_of);
}

}  // namespace

std::vector<int> choose_meshes(const std::vector<Display>& displays) {
  const int n = static_cast<int>(displays.size());
  std::vector<int> mesh_of(displays.size(), 0);
  if (n == 0) return mesh_of;
  std::vector<int> ids(displays.size());
  std::iota(ids.begin(), ids.end(), 0);
  split(displays, std::move(ids), (n + kMaxDisplays - 1) / kMaxDisplays, 0, mesh_of);
  return mesh_of;
}

std::vector<int> share_pipeservers(int pipeservers, const std::vector<long long>& mesh_pixels) {
  const int meshes = static_cast<int>(mesh_pixels.size());
  std::vector<int> share(mesh_pixels.size(), 1);
  const long long total = std::accumulate(mesh_pixels.begin(), mesh_pixels.end(), 0LL);
  const int spare = pipeservers - meshes;
  if (spare <= 0 || total <= 0) return share;
  // The spare pipeservers in proportion to the pixels, the rest by largest remainder.
  std::vector<long long> remainder(mesh_pixels.size());
  int dealt = 0;
  for (int m = 0; m < meshes; ++m) {
    const long double exact = static_cast<long double>(spare) * mesh_pixels[m] / total;
    const int whole = static_cast<int>(exact);
    share[m] += whole;
    dealt += whole;
    remainder[m] = static_cast<long long>((exact - whole) * 1e12L);
  }
  std::vector<int> order(mesh_pixels.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return remainder[a] > remainder[b]; });
  for (int i = 0; dealt < spare; ++i, ++dealt) ++share[order[i % meshes]];
  return share;
}

std::vector<MeshPart> mesh_parts(const Wall& wall) {
  std::vector<MeshPart> parts(static_cast<std::size_t>(wall.mesh_count));
  int first = 0;
  for (int m = 0; m < wall.mesh_count; ++m) {
    MeshPart& p = parts[static_cast<std::size_t>(m)];
    p.mesh = m;
    p.first_pipeserver = first;
    p.pipeserver_count = wall.mesh_count == 1 ? wall.pipeserver_count
                                              : wall.mesh_pipeservers[static_cast<std::size_t>(m)];
    first += p.pipeserver_count;
  }
  for (const Display& d : wall.displays) {
    parts[static_cast<std::size_t>(wall.mesh_count == 1 ? 0 : d.mesh)].displays.push_back(d.id);
  }
  return parts;
}

std::vector<MeshPart> meshes_of(const TileLayout& layout) {
  return layout.meshes.empty() ? mesh_parts(layout.wall) : layout.meshes;
}

Wall mesh_wall(const Wall& wall, const MeshPart& part) {
  Wall w = wall;
  w.displays.clear();
  Rect box{};
  for (int id : part.displays) {
    Display d = wall.displays[static_cast<std::size_t>(id)];
    d.id = static_cast<int>(w.displays.size());
    d.mesh = 0;
    const Rect r = d.on_canvas();
    box = w.displays.empty() ? r
                             : Rect{std::min(box.x, r.x), std::min(box.y, r.y),
                                    std::max(box.right(), r.right()) - std::min(box.x, r.x),
                                    std::max(box.bottom(), r.bottom()) - std::min(box.y, r.y)};
    w.displays.push_back(std::move(d));
  }
  w.mesh_count = 1;
  w.pipeserver_count = part.pipeserver_count;
  w.mesh_pipeservers = {part.pipeserver_count};
  if (wall.mesh_count == 1) return w;
  // The wall's logical tiles, each cut to the box of this mesh's displays, those that reach
  // one of them: the tiles the wall's tiling gives these displays, and no tile of another mesh
  // taken by a pipeserver of this one.
  std::vector<Rect> kept;
  for (const Rect& t : make_logical_tiles(wall)) {
    const Rect cut = intersect(t, box);
    const bool reaches = std::any_of(w.displays.begin(), w.displays.end(), [&](const Display& d) {
      return !intersect(cut, d.on_canvas()).empty();
    });
    if (reaches) kept.push_back(cut);
  }
  w.tiling = TilingSpec{};
  w.tiling.kind = TilingKind::List;
  w.tiling.rects = std::move(kept);
  return w;
}

MeshPlan plan_mesh(const Wall& wall, const MeshPart& part) {
  try {
    return {part, plan_layout(mesh_wall(wall, part))};
  } catch (const LayoutError& e) {
    if (wall.mesh_count == 1) throw;
    throw LayoutError(fmt::format(
        "mesh {} (wall displays {}; pipeservers {}..{} as its inputs "
        "0..{}): {}",
        part.mesh, number_runs(part.displays), part.first_pipeserver,
        part.first_pipeserver + part.pipeserver_count - 1, part.pipeserver_count - 1, e.what()));
  }
}

TileLayout plan_several_meshes(const Wall& wall) {
  TileLayout layout;
  layout.wall = wall;
  layout.meshes = mesh_parts(wall);
  for (const MeshPart& part : layout.meshes) {
    MeshPlan m = plan_mesh(wall, part);
    const int logical_base = static_cast<int>(layout.logical_tiles.size());
    // Its tiles in the wall's numbers, keeping the mesh's display id for the headers.
    const auto to_wall = [&](DisplayTile& t) {
      t.header_display = t.display;
      t.display = part.displays[static_cast<std::size_t>(t.display)];
      t.logical_tile += logical_base;
    };
    layout.logical_tiles.insert(layout.logical_tiles.end(), m.layout.logical_tiles.begin(),
                                m.layout.logical_tiles.end());
    for (std::size_t i = 0; i < m.layout.tiles.size(); ++i) {
      to_wall(m.layout.tiles[i]);
      layout.tiles.push_back(m.layout.tiles[i]);
      layout.tile_pipeserver.push_back(part.first_pipeserver + m.layout.tile_pipeserver[i]);
    }
    for (PipeserverPlan& s : m.layout.pipeservers) {
      s.pipeserver += part.first_pipeserver;
      s.mesh = part.mesh;
      for (PackedTile& p : s.tiles) to_wall(p.tile);
      layout.pipeservers.push_back(std::move(s));
    }
    for (std::string& w : m.layout.warnings) {
      layout.warnings.push_back(fmt::format("mesh {}: {}", part.mesh, w));
    }
  }
  return layout;
}

void require_one_mesh(const Wall& wall, std::string_view what) {
  if (wall.mesh_count <= 1) return;
  const std::string file = wall.source.empty() ? std::string()
                           : wall.meshes_line > 0
                               ? fmt::format("{}:{}: ", wall.source.string(), wall.meshes_line)
                               : wall.source.string() + ": ";
  throw LayoutError(fmt::format(
      "{}the wall's {} displays need {} meshes (a strip header addresses {}); {} drives one "
      "mesh: l2wall run runs every mesh, tilelayout --wall plans and --verify checks them",
      file, wall.displays.size(), wall.mesh_count, kMaxDisplays, what));
}

std::string number_runs(const std::vector<int>& ascending) {
  std::string out;
  for (std::size_t i = 0; i < ascending.size();) {
    std::size_t j = i;
    while (j + 1 < ascending.size() && ascending[j + 1] == ascending[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out +=
        j == i ? fmt::format("{}", ascending[i]) : fmt::format("{}-{}", ascending[i], ascending[j]);
    i = j + 1;
  }
  return out;
}

std::string mesh_heading(const MeshPart& part, int board_rows, int board_columns) {
  const int n = static_cast<int>(part.displays.size());
  const int last = part.first_pipeserver + part.pipeserver_count - 1;
  return fmt::format(
      "mesh {}: {} display{} (wall displays {} as its displays 0-{}), {} pipeserver{} ({}-{} as "
      "its inputs 0-{}), {} x {} boards",
      part.mesh, n, n == 1 ? "" : "s", number_runs(part.displays), n - 1, part.pipeserver_count,
      part.pipeserver_count == 1 ? "" : "s", part.first_pipeserver, last, part.pipeserver_count - 1,
      board_rows, board_columns);
}

}  // namespace l2
