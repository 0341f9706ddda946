// [tiling]: how the canvas is cut into logical tiles. Explicit rectangles are checked here
// (inside the canvas, no overlaps) because only here are their lines known.
#include <fmt/format.h>

#include <algorithm>

#include "strip_headers/strip_header.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

// Bounds the work of planning and the size of plans: a wall with more tiles is a mistake.
constexpr long long kMaxTiles = 65536;
constexpr std::size_t kMaxListTiles = 4096;  // checked pairwise for overlaps

const std::vector<std::string_view> kKinds = {"grid", "list", "kd", "strips"};

// Keys of [tiling] that belong to each kind, in kKinds order.
const std::vector<std::vector<std::string_view>> kKindKeys = {
    {"tile_width", "tile_height"}, {"tiles"}, {"tile_count", "cost"}, {"strips", "substrips"}};

std::string rect_text(const Rect& r) {
  return fmt::format("{}x{} at {},{}", r.w, r.h, r.x, r.y);
}

void read_rects(const TomlFields& f, Wall& wall) {
  const toml::array* tiles = f.array("tiles");
  if (!tiles || tiles->empty() || tiles->size() > kMaxListTiles) {
    f.fail("tiles", "needs 1..4096 tiles [x, y, width, height]");
  }
  std::vector<int> lines;
  for (std::size_t i = 0; i < tiles->size(); ++i) {
    const toml::node& node = *tiles->get(i);
    const std::string name = fmt::format("{}[{}]", f.field("tiles"), i);
    const toml::array* a = node.as_array();
    if (!a || a->size() != 4) {
      f.source().fail(node, name, "must be [x, y, width, height]");
    }
    const Rect r{array_integer(*a->get(0), name + ".x", f.source(), 0, 16383),
                 array_integer(*a->get(1), name + ".y", f.source(), 0, 16383),
                 array_integer(*a->get(2), name + ".width", f.source(), 1, kMaxCoordinate),
                 array_integer(*a->get(3), name + ".height", f.source(), 1, kMaxCoordinate)};
    if (r.right() > wall.canvas_width || r.bottom() > wall.canvas_height) {
      f.source().fail(node, name,
                      fmt::format("tile {} lies outside the {}x{} canvas", rect_text(r),
                                  wall.canvas_width, wall.canvas_height));
    }
    for (std::size_t j = 0; j < wall.tiling.rects.size(); ++j) {
      const Rect overlap = intersect(r, wall.tiling.rects[j]);
      if (!overlap.empty()) {
        f.source().fail(node, name,
                        fmt::format("tile {} overlaps tiles[{}] ({}) in {}", rect_text(r), j,
                                    rect_text(wall.tiling.rects[j]), rect_text(overlap)));
      }
    }
    wall.tiling.rects.push_back(r);
  }
}

void read_cost(const TomlFields& f, Wall& wall) {
  const toml::array* rows = f.array("cost");
  if (!rows) return;  // uniform
  constexpr std::size_t kMaxCells = 256;
  if (rows->empty() || rows->size() > kMaxCells) {
    f.fail("cost", "needs 1..256 rows of numbers");
  }
  double total = 0;
  for (std::size_t r = 0; r < rows->size(); ++r) {
    const std::string name = fmt::format("{}[{}]", f.field("cost"), r);
    const toml::array* row = rows->get(r)->as_array();
    if (!row || row->empty() || row->size() > kMaxCells) {
      f.source().fail(*rows->get(r), name, "must be an array of 1..256 numbers");
    }
    if (r > 0 && row->size() != wall.tiling.cost[0].size()) {
      f.source().fail(*row, name,
                      fmt::format("has {} numbers, but {}[0] has {}", row->size(), f.field("cost"),
                                  wall.tiling.cost[0].size()));
    }
    std::vector<double> values;
    for (std::size_t c = 0; c < row->size(); ++c) {
      const auto v = row->get(c)->value<double>();
      if (!v || *v < 0 || !(*v < 1e12)) {
        f.source().fail(*row->get(c), fmt::format("{}[{}]", name, c),
                        "must be a number from 0 to 1e12");
      }
      values.push_back(*v);
      total += *v;
    }
    wall.tiling.cost.push_back(std::move(values));
  }
  if (total <= 0) f.fail("cost", "needs at least one cell above 0");
}

void check_count(const TomlFields& f, std::string_view key, long long tiles) {
  if (tiles > kMaxTiles) {
    f.fail(key, fmt::format("makes {} tiles, more than {}", tiles, kMaxTiles));
  }
}

}  // namespace

void read_tiling(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("tiling");
  if (!table) top.source().fail(0, "tiling", "missing (required)");
  const TomlFields f(
      *table, "tiling", top.source(),
      {"kind", "tile_width", "tile_height", "tiles", "tile_count", "cost", "strips", "substrips"});
  if (!f.has("kind")) f.fail("kind", "missing (required): grid, list, kd or strips");
  const int kind = f.choice("kind", kKinds, 0);
  // A key of another kind is almost certainly a mistake; say which kind it belongs to.
  for (std::size_t k = 0; k < kKinds.size(); ++k) {
    if (static_cast<int>(k) == kind) continue;
    for (std::string_view key : kKindKeys[k]) {
      if (f.has(key)) {
        f.fail(key, fmt::format("belongs to kind \"{}\", not \"{}\"", kKinds[k], kKinds[kind]));
      }
    }
  }
  wall.tiling_line = f.line_of("kind");
  TilingSpec& t = wall.tiling;
  t.kind = static_cast<TilingKind>(kind);
  switch (t.kind) {
    case TilingKind::Grid:
      t.tile_width = f.required_integer("tile_width", 1, kMaxCoordinate);
      t.tile_height = f.required_integer("tile_height", 1, kMaxCoordinate);
      check_count(f, "tile_width",
                  1LL * ((wall.canvas_width + t.tile_width - 1) / t.tile_width) *
                      ((wall.canvas_height + t.tile_height - 1) / t.tile_height));
      break;
    case TilingKind::List:
      read_rects(f, wall);
      break;
    case TilingKind::KdSplit:
      t.tile_count = f.required_integer(
          "tile_count", 1, std::min<long long>(4096, 1LL * wall.canvas_width * wall.canvas_height));
      wall.tiling_line = f.line_of("tile_count");
      read_cost(f, wall);
      break;
    case TilingKind::Strips:
      t.strip_count = f.required_integer("strips", 1, wall.canvas_height);
      t.substrip_count = f.required_integer("substrips", 1, wall.canvas_width);
      check_count(f, "substrips", 1LL * t.strip_count * t.substrip_count);
      break;
  }
}

void read_pipeservers_and_mesh(const TomlFields& top, Wall& wall) {
  if (const toml::table* mesh = top.table("mesh")) {
    const TomlFields m(*mesh, "mesh", top.source(),
                       {"board_max_width", "board_max_height", "refresh_hz"});
    wall.board_max_width = m.integer("board_max_width", 3, 4096, wall.board_max_width);
    wall.board_max_height = m.integer("board_max_height", 1, 4096, wall.board_max_height);
    wall.refresh_hz = m.integer("refresh_hz", 1, 1000, wall.refresh_hz);
  }
  const toml::table* table = top.table("pipeservers");
  if (!table) top.source().fail(0, "pipeservers", "missing (required)");
  const TomlFields f(*table, "pipeservers", top.source(),
                     {"count", "framebuffer_width", "framebuffer_height", "assignment"});
  // Up to a mesh's inputs for each mesh; read_meshes checks each mesh's share.
  wall.pipeserver_count = f.required_integer("count", 1, kMaxWallPipeservers);
  // A framebuffer is one board input (spec §5): it may not exceed what a board accepts.
  const auto limit = [&](std::string_view key, int board_max, std::string_view mesh_key,
                         int fallback) {
    const int v = f.integer(key, 3, 4096, fallback);
    if (v > board_max) {
      f.fail(key, fmt::format("{} is more than the board input limit {} (raise mesh.{})", v,
                              board_max, mesh_key));
    }
    return v;
  };
  wall.framebuffer_width =
      limit("framebuffer_width", wall.board_max_width, "board_max_width", 1280);
  wall.framebuffer_height =
      limit("framebuffer_height", wall.board_max_height, "board_max_height", 1024);
  wall.framebuffer_line = f.has("framebuffer_height") ? f.line_of("framebuffer_height") : f.line();
  wall.assignment = static_cast<AssignmentPolicy>(
      f.choice("assignment", {"round-robin", "zig-zag", "spiral", "blocks", "area-balanced"}, 0));
}

}  // namespace l2
