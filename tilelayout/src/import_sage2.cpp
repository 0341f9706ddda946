// SAGE2's wall configuration (github.com/SAGE2/SAGE2, config/*-cfg.json): a layout of rows and
// columns of tiles of one resolution; the tile borders, in metres, become mullions in pixels at
// the tiles' own pixel pitch (resolution / tile size in metres); each entry of `displays` is a
// display, spanning `width` x `height` tiles when it says so.
#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "import_formats.hpp"

namespace l2 {
namespace {

struct Borders {
  double left = 0, right = 0, bottom = 0, top = 0;
};

// `tile_borders` as an object {left, right, bottom, top} or an array [left, right, bottom, top],
// in metres (SAGE2's configurations use both).
Borders read_borders(const JsonAt& b) {
  Borders out;
  if (!b.present()) return out;
  double* const sides[] = {&out.left, &out.right, &out.bottom, &out.top};
  const char* const names[] = {"left", "right", "bottom", "top"};
  const bool array = b.json().is_array();
  if (!array) b.object();
  if (array && b.array_size() != 4)
    b.expected("an object {left, right, bottom, top} or an array of those 4 numbers");
  for (int i = 0; i < 4; ++i) {
    const JsonAt v = array ? b[static_cast<std::size_t>(i)] : b[names[i]];
    *sides[i] = v.number_or(0);
    if (*sides[i] < 0) v.expected("a width in metres, 0 or more");
  }
  return out;
}

// Metres to pixels at `per_metre`, refused past what a wall file takes.
int pixels(const JsonAt& where, double metres, double per_metre) {
  if (metres == 0) return 0;
  const double px = std::round(metres * per_metre);
  if (!(px <= kMaxImportedSide)) {  // also a pitch so fine that it is not a number
    where.fail(fmt::format("tile borders of {} m are {} pixels at the tiles' pitch, more than {}",
                           metres, px, kMaxImportedSide));
  }
  return static_cast<int>(px);
}

}  // namespace

WallDraft import_sage2(const JsonAt& root, const std::string& name) {
  const std::string& file = root.file();
  const JsonAt layout = root["layout"];
  layout.object();
  const int rows = layout["rows"].positive(kMaxImportedDisplays);
  const int columns = layout["columns"].positive(kMaxImportedDisplays);
  const JsonAt resolution = root["resolution"];
  resolution.object();
  const int width = resolution["width"].positive(kMaxImportedSide);
  const int height = resolution["height"].positive(kMaxImportedSide);

  WallDraft d;
  d.name = root["name"].string_or(name);
  d.header.push_back(
      fmt::format("Imported by tilelayout import from {} (SAGE2 wall configuration).", file));
  int mx = 0, my = 0;
  const JsonAt dims = root["dimensions"];
  if (dims.present()) {
    dims.object();
    const double tw = dims["tile_width"].number(), th = dims["tile_height"].number();
    if (tw <= 0) dims["tile_width"].expected("a width in metres, more than 0");
    if (th <= 0) dims["tile_height"].expected("a height in metres, more than 0");
    const Borders b = read_borders(dims["tile_borders"]);
    // Between two tiles: one tile's right border and the next one's left, and so on.
    mx = pixels(dims["tile_borders"], b.left + b.right, width / tw);
    my = pixels(dims["tile_borders"], b.top + b.bottom, height / th);
    d.header.push_back(fmt::format(
        "layout {}x{} tiles of {}x{} pixels; tiles {} m x {} m, borders {} m + {} m across and "
        "{} m + {} m down: mullions {} and {} pixels at the tiles' pixel pitch.",
        columns, rows, width, height, tw, th, b.right, b.left, b.bottom, b.top, mx, my));
  } else {
    d.header.push_back(
        fmt::format("layout {}x{} tiles of {}x{} pixels.", columns, rows, width, height));
    d.notes.push_back("no dimensions (tile sizes and borders in metres): mullions taken as 0");
  }

  const JsonAt displays = root["displays"];
  const std::size_t n = displays.array_size();
  if (n == 0) displays.fail("expected at least one display, got none");
  if (n > static_cast<std::size_t>(kMaxImportedDisplays))
    too_many_displays(file, displays.path(), static_cast<long long>(n));
  // Which display covers each tile, to refuse two on one tile.
  std::vector<int> owner(static_cast<std::size_t>(rows * columns), -1);
  bool all_single = true;
  int with_host = 0;
  std::vector<std::string> hosts;
  for (std::size_t k = 0; k < n; ++k) {
    const JsonAt e = displays[k];
    e.object();
    const int row = static_cast<int>(e["row"].integer(0, rows - 1));
    const int column = static_cast<int>(e["column"].integer(0, columns - 1));
    const int span_w = static_cast<int>(e["width"].integer_or(1, columns - column, 1));
    const int span_h = static_cast<int>(e["height"].integer_or(1, rows - row, 1));
    for (int r = row; r < row + span_h; ++r) {
      for (int c = column; c < column + span_w; ++c) {
        int& o = owner[static_cast<std::size_t>(r * columns + c)];
        if (o >= 0)
          e.fail(
              fmt::format("covers row {}, column {}, which displays[{}] covers already", r, c, o));
        o = static_cast<int>(k);
      }
    }
    DraftDisplay p;
    // A display spanning tiles is one picture across them, their borders included.
    p.width = span_w * width + (span_w - 1) * mx;
    p.height = span_h * height + (span_h - 1) * my;
    if (p.width > kMaxImportedSide || p.height > kMaxImportedSide) {
      e.fail(fmt::format("spans {}x{} pixels, more than the {} a display may have", p.width,
                         p.height, kMaxImportedSide));
    }
    p.x = column * (width + mx);
    p.y = row * (height + my);
    const std::string host = e["host"].string_or("");
    if (!host.empty()) {
      ++with_host;
      hosts.push_back(host);
    }
    p.origin = fmt::format(
        "displays[{}], row {} column {}{}{}", k, row, column,
        span_w > 1 || span_h > 1 ? fmt::format(", spanning {}x{} tiles", span_w, span_h) : "",
        host.empty() ? "" : ", on " + host);
    if (span_w > 1 || span_h > 1) {
      all_single = false;
      d.notes.push_back(fmt::format(
          "displays[{}] spans {}x{} tiles: imported as one {}x{} display, the borders between "
          "its tiles inside it",
          k, span_w, span_h, p.width, p.height));
    }
    d.displays.push_back(p);
  }
  if (with_host == static_cast<int>(n)) {
    d.hosts = hosts;
  } else if (with_host > 0) {
    d.notes.push_back(
        fmt::format("only {} of the {} displays name a host: one pipeserver per display, no hosts",
                    with_host, n));
  }
  // Every tile a display of its own: the grid, its ids row by row.
  if (all_single && static_cast<int>(n) == rows * columns) {
    std::vector<DraftDisplay> in_grid(n);
    for (std::size_t t = 0; t < n; ++t) in_grid[t] = d.displays[static_cast<std::size_t>(owner[t])];
    d.displays = in_grid;
    d.grid = DraftGrid{columns, rows, width, height, mx, my};
  }
  return d;
}

}  // namespace l2
