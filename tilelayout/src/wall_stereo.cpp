// `stereo` (docs/wall-file.md, "Stereo walls"): written at the top level as `stereo = "passive"`
// or as a [stereo] section with `mode`, `eye_separation` and `convergence` (TOML reads an inline
// table and the section alike); and each display's `eye`. A passive wall's displays come in
// twins, one per eye, covering the same canvas rectangle and swapping together, so each eye's
// displays show the whole picture and both eyes of a frame are shown in the same refresh. An
// active wall's displays have no eye: each shows both, one refresh after the other, all in one
// swap group. A packed wall's displays (side-by-side, top-bottom) have no eye either: each shows
// both at once, one in each half of its raster (wall.hpp's display_parts).
#include <fmt/format.h>

#include <algorithm>

#include "wall_sections.hpp"

namespace l2 {
namespace {

const std::vector<std::string_view> kModes{std::begin(kStereoModeNames) + 1,
                                           std::end(kStereoModeNames)};

std::string quoted_modes() {
  std::string text;
  for (std::size_t i = 0; i < kModes.size(); ++i)
    text += fmt::format("{}\"{}\"",
                        i == 0                   ? ""
                        : i + 1 == kModes.size() ? " or "
                                                 : ", ",
                        kModes[i]);
  return text;
}

// `key` of `f`: `stereo` at the top level, `mode` of the section.
StereoMode mode_named(const TomlFields& f, std::string_view key, const std::string& name) {
  const auto it = std::find(kModes.begin(), kModes.end(), name);
  if (it == kModes.end()) f.fail(key, fmt::format("must be {}, got \"{}\"", quoted_modes(), name));
  return static_cast<StereoMode>(it - kModes.begin() + 1);
}

// The line of the [[display]] entry (or the grid) that gave display `id`, for errors.
int display_line(const TomlFields& top, int id) {
  if (const toml::table* grid = top.table("display_grid")) return line_of(*grid);
  const toml::array& list = *top.node("display")->as_array();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const toml::table& t = *list.get(i)->as_table();
    if (t["id"].value<long long>().value_or(static_cast<long long>(i)) == id)
      return line_of(*list.get(i));
  }
  return 0;
}

std::string named(const Display& d) {
  const Rect r = d.on_canvas();
  return fmt::format("display {} (eye = \"{}\", {}x{} at {},{})", d.id,
                     kEyeNames[static_cast<int>(d.eye)], r.w, r.h, r.x, r.y);
}

// A passive grid is written once: its displays are the left eye's, and the same displays again,
// numbered on from them, are the right eye's (without monitor names: those name one monitor).
void twin_grid(Wall& wall) {
  const std::size_t n = wall.displays.size();
  for (std::size_t i = 0; i < n; ++i) {
    Display right = wall.displays[i];
    wall.displays[i].eye = Eye::Left;
    right.eye = Eye::Right;
    right.id = static_cast<int>(n + i);
    right.monitor.clear();
    wall.displays.push_back(right);
  }
}

// Every display of a passive wall has exactly one twin of the other eye on its canvas
// rectangle, in its swap group; no display of another wall has an eye.
void check_eyes(const TomlFields& top, const Wall& wall) {
  const auto fail = [&](const Display& d, const std::string& why) {
    top.source().fail(display_line(top, d.id), fmt::format("display {}", d.id), why);
  };
  const bool passive = wall.stereo.mode == StereoMode::Passive;
  for (const Display& d : wall.displays) {
    if (!passive && d.eye != Eye::None) fail(d, "eye is only for a wall with stereo = \"passive\"");
    if (passive && d.eye == Eye::None)
      fail(d, "eye missing: every display of a passive stereo wall shows \"left\" or \"right\"");
    if (!passive) continue;
    int same = 0, other = 0;
    const Display* twin = nullptr;
    for (const Display& e : wall.displays) {
      if (e.on_canvas() != d.on_canvas()) continue;
      if (e.eye == d.eye) ++same;
      if (e.eye != d.eye) ++other, twin = &e;
    }
    if (same > 1)
      fail(d,
           fmt::format("{}: another display of the same eye covers the same rectangle", named(d)));
    if (other != 1 || !twin)
      fail(d, fmt::format("{}: no display of the other eye covers the same canvas rectangle "
                          "(each eye's display needs a twin of the other eye at the same x, y "
                          "and size)",
                          named(d)));
    if (twin->swap_group != d.swap_group)
      fail(d, fmt::format("swap_group {}, but its twin display {} has {}: both eyes of a frame "
                          "swap together",
                          d.swap_group, twin->id, twin->swap_group));
  }
}

// One pair of shutter glasses sees every display of an active wall: a display in another swap
// group could show the other eye in the same refresh.
void check_one_shutter(const TomlFields& top, const Wall& wall) {
  if (wall.stereo.mode != StereoMode::Active) return;
  for (const Display& d : wall.displays) {
    if (d.swap_group == wall.displays.front().swap_group) continue;
    top.source().fail(
        display_line(top, d.id), fmt::format("display {}", d.id),
        fmt::format("swap_group {}, but display {} has {}: every display of an "
                    "active stereo wall shows the same eye in each refresh",
                    d.swap_group, wall.displays.front().id, wall.displays.front().swap_group));
  }
}

// A packed display shows each eye in one half of its raster, as the display unpacks it: its
// halves are whole pixels, and what changes pixels after the tiles (a warp, alpha and beta
// maps) or turns its raster would move pixels across the halves or put them in the wrong one.
void check_packed(const TomlFields& top, const Wall& wall) {
  if (!packed_stereo(wall.stereo)) return;
  const bool side = wall.stereo.mode == StereoMode::SideBySide;
  const char* mode = side ? "side-by-side" : "top-bottom";
  for (const Display& d : wall.displays) {
    const auto fail = [&](const std::string& why) {
      top.source().fail(display_line(top, d.id), fmt::format("display {}", d.id),
                        fmt::format("{} stereo: {}", mode, why));
    };
    const int length = side ? d.width : d.height;
    if (length % 2 != 0)
      fail(fmt::format("{} {} is odd: each eye takes exactly half of it", side ? "width" : "height",
                       length));
    if (!d.orientation.identity())
      fail("rotation and flip are not supported (each eye's half is in the panel's own raster)");
    if (!d.warp.empty()) fail("warp is not supported (it would move pixels across the halves)");
    if (!d.alpha.empty() || !d.beta.empty())
      fail("alpha and beta maps are not supported (they are drawn for the unpacked picture)");
  }
}

}  // namespace

void read_stereo(const TomlFields& top, Wall& wall) {
  if (!top.has("stereo")) return;
  const toml::node& n = *top.node("stereo");
  StereoSpec& s = wall.stereo;
  s.line = line_of(n);
  if (const auto text = n.value<std::string>()) {
    s.mode = mode_named(top, "stereo", *text);
  } else if (const toml::table* table = n.as_table()) {
    const TomlFields f(*table, "stereo", top.source(), {"mode", "eye_separation", "convergence"});
    const auto mode = f.string("mode");
    if (!mode) f.fail("mode", fmt::format("missing (required): {}", quoted_modes()));
    s.mode = mode_named(f, "mode", *mode);
    s.line = f.line_of("mode");
    s.eye_separation = f.fraction("eye_separation", 0, kMaxEyeSeparation, s.eye_separation);
    s.convergence = f.fraction("convergence", 0, kMaxConvergence, s.convergence);
  } else {
    top.fail("stereo",
             fmt::format("must be {} or a [stereo] section, got {}", quoted_modes(), type_name(n)));
  }
}

void read_stereo_displays(const TomlFields& top, Wall& wall) {
  if (wall.stereo.mode == StereoMode::Passive && top.table("display_grid")) twin_grid(wall);
  check_eyes(top, wall);
  check_one_shutter(top, wall);
  check_packed(top, wall);
}

void check_stereo(const TomlFields& top, const Wall& wall) {
  if (!wall.stereo.on()) return;
  const auto refuse = [&](int line, std::string_view field, std::string_view what) {
    top.source().fail(line, field, fmt::format("stereo walls do not support {} yet", what));
  };
  if (wall.mesh_count > 1) refuse(wall.meshes_line, "display", "several meshes");
  if (wall.depth_layers != 0) refuse(wall.depth_line, "depth", "depth compositing");
  if (wall.overlay) refuse(wall.overlay->line, "overlay", "an overlay");
  if (wall.balance.balancing() || wall.balance.survive_host_loss)
    refuse(wall.balance.line, "balance", "balancing");
  // Twins overlap wholly: blending them would halve each eye's light.
  if (wall.blend.on) refuse(wall.blend.line, "blend", "blending");
}

}  // namespace l2
