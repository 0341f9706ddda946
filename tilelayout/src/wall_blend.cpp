// `blend`: edge blending of overlapping projectors (docs/wall-file.md, "Blending overlapping
// projectors"). Written at the top level as `blend = "linear"` or `blend = { gamma = 2.2 }`, or
// as a [blend] section with `gamma`: TOML reads the inline table and the section alike.
#include <fmt/format.h>

#include "tilelayout/blend_map.hpp"
#include "wall_sections.hpp"

namespace l2 {

void read_blend(const TomlFields& top, Wall& wall) {
  if (!top.has("blend")) return;
  const toml::node& n = *top.node("blend");
  const std::string wanted =
      fmt::format("must be \"linear\" or {{ gamma = 1..{} }}", kMaxBlendGamma);
  wall.blend.line = line_of(n);
  if (const auto text = n.value<std::string>()) {
    if (*text != "linear") top.fail("blend", fmt::format("{}, got \"{}\"", wanted, *text));
    wall.blend.on = true;
    wall.blend.gamma = 1.0;
  } else if (const toml::table* table = n.as_table()) {
    const TomlFields f(*table, "blend", top.source(), {"gamma"});
    if (!f.has("gamma")) f.fail("gamma", fmt::format("required: a number 1..{}", kMaxBlendGamma));
    const toml::node& g = *f.node("gamma");
    const auto v = g.value<double>();  // an integer too
    if (!v)
      f.fail("gamma", fmt::format("must be a number 1..{}, got {}", kMaxBlendGamma, type_name(g)));
    if (!(*v >= 1 && *v <= kMaxBlendGamma))
      f.fail("gamma", fmt::format("must be a number 1..{}, got {}", kMaxBlendGamma, *v));
    wall.blend.on = true;
    wall.blend.gamma = *v;
  } else {
    top.fail("blend", fmt::format("{}, got {}", wanted, type_name(n)));
  }
  // Blending weighs the overlaps the displays' rectangles declare; without one it would do
  // nothing, which is more likely a mistake (a mullion no longer negative) than a wish.
  for (const Display& d : wall.displays)
    if (blend_ramps(wall, d.id).any()) return;
  top.fail("blend",
           "no two displays overlap: nothing to blend (a negative mullion, or "
           "[[display]] rectangles that overlap, declare an overlap)");
}

}  // namespace l2
