// [display_grid], [[display]] and [canvas]: where every output display sits on the canvas.
#include <fmt/format.h>

#include <algorithm>

#include "strip_headers/strip_header.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

constexpr int kMaxCanvas = kMaxCanvasSide;
constexpr int kMaxSize = kMaxCoordinate;  // display sizes are: x, y, width have 12 bits

// `rotation` and `flip` of a display, or of every display of a grid: the panel as mounted.
Orientation read_orientation(const TomlFields& f) {
  Orientation o;
  if (const auto r = f.integer("rotation", 0, 270)) {
    if (*r % 90 != 0) f.fail("rotation", fmt::format("must be 0, 90, 180 or 270, got {}", *r));
    o.rotation = *r;
  }
  o.flip = static_cast<Flip>(f.choice("flip", {std::begin(kFlipNames), std::end(kFlipNames)}, 0));
  return o;
}

// Meshes given per display (`meshes` of a grid, `mesh` of a [[display]]) must be given for
// every display or none, numbered 0.. without gaps, each of at most 64 displays: a strip
// header addresses no more. `fail(i, why)` reports display i's.
template <typename Fail>
void check_given_meshes(const std::vector<Display>& displays, const Fail& fail) {
  const auto given = [](const Display& d) { return d.mesh >= 0; };
  const auto first_given = std::find_if(displays.begin(), displays.end(), given);
  if (first_given == displays.end()) return;
  const auto first_missing = std::find_if_not(displays.begin(), displays.end(), given);
  if (first_missing != displays.end()) {
    fail(static_cast<int>(first_missing - displays.begin()),
         fmt::format("missing, but display {} has one: give every display a mesh or none (then "
                     "the planner chooses)",
                     first_given->id));
  }
  std::vector<int> count(kMaxMeshes, 0);
  for (const Display& d : displays) ++count[static_cast<std::size_t>(d.mesh)];
  for (std::size_t i = 0; i < displays.size(); ++i) {
    const int m = displays[i].mesh;
    if (m > 0 && count[static_cast<std::size_t>(m - 1)] == 0) {
      fail(static_cast<int>(i), fmt::format("{}, but no display has mesh {}: meshes are "
                                            "numbered 0.. without gaps",
                                            m, m - 1));
    }
    if (count[static_cast<std::size_t>(m)] > kMaxDisplays) {
      fail(static_cast<int>(i),
           fmt::format("mesh {} has {} displays, more than the {} a strip header addresses", m,
                       count[static_cast<std::size_t>(m)], kMaxDisplays));
    }
  }
}

// Optional per-display values of a grid, one per display in id order.
void read_grid_lists(const TomlFields& f, std::vector<Display>& displays) {
  const int n = static_cast<int>(displays.size());
  if (const toml::array* meshes = f.array("meshes")) {
    if (static_cast<int>(meshes->size()) != n) {
      f.fail("meshes",
             fmt::format("needs {} entries (one per display), got {}", n, meshes->size()));
    }
    for (int i = 0; i < n; ++i) {
      displays[i].mesh = array_integer(*meshes->get(i), fmt::format("{}[{}]", f.field("meshes"), i),
                                       f.source(), 0, kMaxMeshes - 1);
    }
  }
  if (const toml::array* groups = f.array("swap_groups")) {
    if (static_cast<int>(groups->size()) != n) {
      f.fail("swap_groups",
             fmt::format("needs {} entries (one per display), got {}", n, groups->size()));
    }
    for (int i = 0; i < n; ++i) {
      displays[i].swap_group =
          array_integer(*groups->get(i), fmt::format("{}[{}]", f.field("swap_groups"), i),
                        f.source(), 0, kMaxDisplays - 1);
    }
  }
  if (const toml::array* monitors = f.array("monitors")) {
    if (static_cast<int>(monitors->size()) != n) {
      f.fail("monitors",
             fmt::format("needs {} entries (one per display), got {}", n, monitors->size()));
    }
    for (int i = 0; i < n; ++i) {
      const toml::node& m = *monitors->get(i);
      if (!m.is_string()) {
        f.source().fail(m, fmt::format("{}[{}]", f.field("monitors"), i),
                        fmt::format("must be a string, got {}", type_name(m)));
      }
      displays[i].monitor = m.as_string()->get();
    }
  }
}

void read_grid(const TomlFields& top, const toml::table& table, Wall& wall) {
  const TomlFields f(
      table, "display_grid", top.source(),
      {"columns", "rows", "width", "height", "mullion_x", "mullion_y", "origin_x", "origin_y",
       "swap_groups", "monitors", "meshes", "rotation", "flip", "colour"});
  const int columns = f.required_integer("columns", 1, kMaxWallDisplays);
  const int rows = f.required_integer("rows", 1, kMaxWallDisplays);
  if (columns * rows > kMaxWallDisplays) {
    f.fail("rows", fmt::format("{}x{} displays are more than the {} of {} meshes", columns, rows,
                               kMaxWallDisplays, kMaxMeshes));
  }
  const int pw = f.required_integer("width", 1, kMaxSize);
  const int ph = f.required_integer("height", 1, kMaxSize);
  const Orientation orientation = read_orientation(f);
  // Mullions and the grid's steps are on the canvas, where a turned panel is its size turned.
  const int w = orientation.turned() ? ph : pw, h = orientation.turned() ? pw : ph;
  // A negative mullion is projector overlap; it must leave each display some pixels of its own.
  const int mx = f.integer("mullion_x", -(w - 1), kMaxSize, 0);
  const int my = f.integer("mullion_y", -(h - 1), kMaxSize, 0);
  const int ox = f.integer("origin_x", 0, kMaxCanvas - 1, 0);
  const int oy = f.integer("origin_y", 0, kMaxCanvas - 1, 0);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      Display d;
      d.id = r * columns + c;
      d.width = pw;
      d.height = ph;
      d.orientation = orientation;
      d.mesh = -1;  // the planner's choice unless `meshes` gives it
      d.canvas_x = ox + c * (w + mx);
      d.canvas_y = oy + r * (h + my);
      wall.displays.push_back(d);
    }
  }
  read_grid_lists(f, wall.displays);
  read_grid_colour(f, wall.displays);
  check_given_meshes(wall.displays, [&](int i, const std::string& why) {
    f.fail("meshes", fmt::format("display {}: {}", i, why));
  });
}

void read_list(const TomlFields& top, const toml::array& list, Wall& wall) {
  std::vector<int> lines;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string name = fmt::format("display[{}]", i);
    const toml::node& node = *list.get(i);
    if (!node.is_table()) {
      top.source().fail(node, name, fmt::format("must be a table, got {}", type_name(node)));
    }
    const TomlFields f(
        *node.as_table(), name, top.source(),
        {"id", "mesh", "width", "height", "x", "y", "swap_group", "monitor", "rotation", "flip",
         "gain", "offset", "lut", "warp", "alpha", "beta", "alpha_gamma", "eye"});
    Display d;
    d.id = f.integer("id", 0, kMaxWallDisplays - 1, static_cast<int>(i));
    d.mesh = f.integer("mesh", 0, kMaxMeshes - 1, -1);
    d.width = f.required_integer("width", 1, kMaxSize);
    d.height = f.required_integer("height", 1, kMaxSize);
    d.canvas_x = f.required_integer("x", 0, kMaxCanvas - 1);
    d.canvas_y = f.required_integer("y", 0, kMaxCanvas - 1);
    d.swap_group = f.integer("swap_group", 0, kMaxDisplays - 1, 0);
    d.monitor = f.string("monitor").value_or("");
    d.orientation = read_orientation(f);
    d.colour = read_colour(f);
    read_warp(f, d);
    read_levels(f, d);
    d.eye = static_cast<Eye>(f.choice("eye", {"left", "right"}, -1) + 1);
    for (std::size_t j = 0; j < wall.displays.size(); ++j) {
      if (wall.displays[j].id == d.id) {
        f.fail("id", fmt::format("{} is already the id of display[{}]", d.id, j));
      }
    }
    wall.displays.push_back(d);
    lines.push_back(f.line());
  }
  check_given_meshes(wall.displays, [&](int i, const std::string& why) {
    top.source().fail(lines[static_cast<std::size_t>(i)], fmt::format("display[{}].mesh", i), why);
  });
  // Display ids are array indices everywhere downstream (Wall::displays[i].id == i).
  std::sort(wall.displays.begin(), wall.displays.end(),
            [](const Display& a, const Display& b) { return a.id < b.id; });
  for (int i = 0; i < static_cast<int>(wall.displays.size()); ++i) {
    if (wall.displays[i].id != i) {
      top.source().fail(lines.back(), "display",
                        fmt::format("ids must run 0..{} without gaps; id {} is missing",
                                    wall.displays.size() - 1, i));
    }
  }
}

}  // namespace

void read_displays(const TomlFields& top, Wall& wall) {
  const toml::table* grid = top.table("display_grid");
  const toml::node* entries = top.node("display");
  if (entries && !entries->is_array()) {
    top.fail("display", fmt::format("must be [[display]] entries (an array of tables), got {}",
                                    type_name(*entries)));
  }
  const toml::array* list = entries ? entries->as_array() : nullptr;
  if (grid && list) {
    top.fail("display", "use either [display_grid] or [[display]], not both");
  }
  if (grid) {
    read_grid(top, *grid, wall);
  } else if (list && !list->empty()) {
    read_list(top, *list, wall);
  } else {
    top.source().fail(0, "display_grid",
                      "the wall has no displays ([display_grid] or [[display]])");
  }
}

void read_canvas(const TomlFields& top, Wall& wall) {
  int right = 0, bottom = 0;
  for (const Display& d : wall.displays) {
    right = std::max(right, d.on_canvas().right());
    bottom = std::max(bottom, d.on_canvas().bottom());
  }
  wall.canvas_width = right;
  wall.canvas_height = bottom;
  const toml::table* table = top.table("canvas");
  if (!table) {
    if (right > kMaxCanvas || bottom > kMaxCanvas || 1LL * right * bottom > kMaxCanvasArea) {
      top.source().fail(0, "display",
                        fmt::format("the displays span {}x{} pixels, more than a canvas may have "
                                    "({} a side, {} in all)",
                                    right, bottom, kMaxCanvas, kMaxCanvasArea));
    }
    return;
  }
  const TomlFields f(*table, "canvas", top.source(), {"width", "height"});
  wall.canvas_width = f.required_integer("width", 1, kMaxCanvas);
  wall.canvas_height = f.required_integer("height", 1, kMaxCanvas);
  if (1LL * wall.canvas_width * wall.canvas_height > kMaxCanvasArea) {
    f.fail("height", fmt::format("a {}x{} canvas is more than the {} pixels a canvas may have",
                                 wall.canvas_width, wall.canvas_height, kMaxCanvasArea));
  }
  for (const Display& d : wall.displays) {
    const Rect r = d.on_canvas();
    if (r.right() > wall.canvas_width || r.bottom() > wall.canvas_height) {
      f.fail(r.right() > wall.canvas_width ? "width" : "height",
             fmt::format("display {} ({}x{} at {},{}) extends past the {}x{} canvas", d.id, r.w,
                         r.h, d.canvas_x, d.canvas_y, wall.canvas_width, wall.canvas_height));
    }
  }
}

}  // namespace l2
