// [depth] and [overlay]: the compositing strips of spec §7 a wall asks for. Read after
// [pipeservers], since both depend on how many pipeservers there are.
#include <fmt/format.h>

#include <string>
#include <vector>

#include "strip_headers/strip_header.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

// The pipeservers that share the tiling: all but the overlay's own.
int tile_pipeservers(const Wall& wall) {
  return wall.pipeserver_count - (wall.overlay ? 1 : 0);
}

std::string divisors(int n) {
  std::vector<std::string> out;
  for (int k = 1; k <= n; ++k) {
    if (n % k == 0) out.push_back(std::to_string(k));
  }
  std::string text;
  for (std::size_t i = 0; i < out.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == out.size() ? " or " : ", ") + out[i];
  }
  return text;
}

void read_depth(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("depth");
  if (!table) return;
  const TomlFields f(*table, "depth", top.source(), {"layers"});
  const toml::node* layers = f.node("layers");
  if (!layers) f.fail("layers", "missing (required): a number of layers or \"all\"");
  wall.depth_line = f.line_of("layers");
  const int pipeservers = tile_pipeservers(wall);
  if (const auto* s = layers->as_string()) {
    if (s->get() != "all") {
      f.fail("layers", fmt::format("must be 1..{} or \"all\", got \"{}\"", pipeservers, s->get()));
    }
    wall.depth_layers = kAllLayers;
    return;
  }
  if (!layers->is_integer()) {
    f.fail("layers", fmt::format("must be an integer or \"all\", got {}", type_name(*layers)));
  }
  const long long k = layers->as_integer()->get();
  if (k < 1 || k > pipeservers) {
    f.fail("layers", fmt::format("must be 1..{} or \"all\", got {}", pipeservers, k));
  }
  // Each layer is rendered by its own pipeservers, the same number for every layer.
  if (pipeservers % k != 0) {
    f.fail("layers", fmt::format("{} layers do not share {} pipeservers evenly: {}", k, pipeservers,
                                 divisors(pipeservers)));
  }
  wall.depth_layers = static_cast<int>(k);
}

void read_overlay(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("overlay");
  if (!table) return;
  const TomlFields f(*table, "overlay", top.source(),
                     {"display", "x", "y", "width", "height", "key"});
  const int last_display = static_cast<int>(wall.displays.size()) - 1;
  Overlay o;
  o.line = f.line();
  o.display = f.integer("display", 0, last_display, 0);
  o.on_display = {f.required_integer("x", 0, kMaxCoordinate),
                  f.required_integer("y", 0, kMaxCoordinate),
                  f.required_integer("width", 1, kMaxCoordinate),
                  f.required_integer("height", 1, kMaxCoordinate)};
  o.key = static_cast<std::uint32_t>(f.integer("key", 0, 0xFFFFFF, 0));
  const Display& d = wall.displays[static_cast<std::size_t>(o.display)];
  const Rect& r = o.on_display;
  if (r.right() > d.width || r.bottom() > d.height) {
    top.source().fail(o.line, "overlay",
                      fmt::format("{}x{} at {},{} does not lie on display {} ({}x{})", r.w, r.h,
                                  r.x, r.y, d.id, d.width, d.height));
  }
  if (wall.pipeserver_count < 2) {
    top.source().fail(o.line, "overlay",
                      fmt::format("needs a pipeserver of its own besides those of the tiles: "
                                  "pipeservers.count must be at least 2, got {}",
                                  wall.pipeserver_count));
  }
  wall.overlay = o;
}

}  // namespace

void read_compositing(const TomlFields& top, Wall& wall) {
  read_overlay(top, wall);
  read_depth(top, wall);
}

}  // namespace l2
