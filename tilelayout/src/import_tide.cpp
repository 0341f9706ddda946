// Tide's JSON configuration (github.com/BlueBrain/Tide, examples/configuration_*.json): the
// first surface's screens, each of displaysPerScreenX x displaysPerScreenY displays, as one
// display grid with the bezels as mullions; the processes' hosts as pipeservers.
#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <utility>

#include "import_formats.hpp"

namespace l2 {
namespace {

// The newer key, or the one older Tide examples use.
JsonAt either(const JsonAt& surface, const char* key, const char* old_key) {
  const JsonAt v = surface[key];
  return v.present() || !surface[old_key].present() ? v : surface[old_key];
}

int count_or_one(const JsonAt& v) {
  return v.present() ? v.positive(kMaxImportedDisplays) : 1;
}

struct Driver {
  int process = 0;
  std::string host, display;
};

}  // namespace

WallDraft import_tide(const JsonAt& root, const std::string& name) {
  const std::string& file = root.file();
  const JsonAt surfaces = root["surfaces"];
  if (surfaces.array_size() == 0) surfaces.fail("expected at least one surface, got none");
  const JsonAt s = surfaces[0];
  s.object();
  const int screens_x = count_or_one(either(s, "screenCountX", "numScreensX"));
  const int screens_y = count_or_one(either(s, "screenCountY", "numScreensY"));
  const int per_x = count_or_one(s["displaysPerScreenX"]);
  const int per_y = count_or_one(s["displaysPerScreenY"]);
  const int columns = screens_x * per_x, rows = screens_y * per_y;
  if (columns * rows > kMaxImportedDisplays) {
    too_many_displays(file, s.path(), static_cast<long long>(columns) * rows);
  }
  DraftGrid g;
  g.columns = columns;
  g.rows = rows;
  g.width = s["displayWidth"].positive(kMaxImportedSide);
  g.height = s["displayHeight"].positive(kMaxImportedSide);
  // A negative bezel overlaps neighbours (projectors); each keeps at least a pixel of its own.
  g.mullion_x = static_cast<int>(s["bezelWidth"].integer_or(-(g.width - 1), kMaxImportedSide, 0));
  g.mullion_y = static_cast<int>(s["bezelHeight"].integer_or(-(g.height - 1), kMaxImportedSide, 0));

  WallDraft d;
  d.name = root["settings"]["infoName"].string_or(name);
  d.grid = g;
  d.header.push_back(
      fmt::format("Imported by tilelayout import from {} (Tide JSON configuration).", file));
  d.header.push_back(fmt::format(
      "surfaces[0]: {}x{} screens of {}x{} displays each, {}x{} pixels a display; bezels {} and "
      "{} pixels are the mullions{}.",
      screens_x, screens_y, per_x, per_y, g.width, g.height, g.mullion_x, g.mullion_y,
      g.mullion_x < 0 || g.mullion_y < 0 ? " (negative: projectors overlapping)" : ""));
  if (surfaces.array_size() > 1) {
    d.notes.push_back(
        fmt::format("surfaces[1..{}]: only surfaces[0] is imported; a wall file is one canvas",
                    surfaces.array_size() - 1));
  }

  // Which process drives each screen of surface 0, by (i, j); the first one that names it.
  std::map<std::pair<int, int>, Driver> drivers;
  std::string stereo, repeated;
  int stereo_count = 0, repeated_count = 0;
  const JsonAt processes = root["processes"];
  const std::size_t process_count = processes.present() ? processes.array_size() : 0;
  for (std::size_t k = 0; k < process_count; ++k) {
    const JsonAt p = processes[k];
    const std::string host = p["host"].string();
    const JsonAt screens = p["screens"];
    bool on_surface = false;
    for (std::size_t n = 0; n < screens.array_size(); ++n) {
      const JsonAt sc = screens[n];
      sc.object();
      if (sc["surface"].integer_or(0, INT32_MAX, 0) != 0) continue;
      on_surface = true;
      const int i = static_cast<int>(sc["i"].integer_or(0, screens_x - 1, 0));
      const int j = static_cast<int>(sc["j"].integer_or(0, screens_y - 1, 0));
      const std::string mode = sc["stereo"].string_or("mono");
      if (mode != "mono" && stereo_count++ == 0)
        stereo = fmt::format("{} = \"{}\"", sc["stereo"].path(), mode);
      const auto [it, added] = drivers.try_emplace(
          {i, j}, Driver{static_cast<int>(k), host, sc["display"].string_or("")});
      if (!added && repeated_count++ == 0)
        repeated = fmt::format("{} shows screen i={} j={} again (processes[{}] does first)",
                               sc.path(), i, j, it->second.process);
    }
    if (on_surface) d.hosts.push_back(host);
  }
  if (stereo_count > 0) {
    d.notes.push_back(fmt::format(
        "stereo: {}{}: not representable, each display is imported once, as one picture", stereo,
        stereo_count > 1 ? fmt::format(" and {} more screens", stereo_count - 1) : ""));
  }
  if (repeated_count > 0) {
    d.notes.push_back(fmt::format(
        "{}{}: kept once", repeated,
        repeated_count > 1 ? fmt::format(" (and {} more repeated screens)", repeated_count - 1)
                           : ""));
  }
  int undriven = 0;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const int i = c / per_x, j = r / per_y;
      DraftDisplay p;
      p.width = g.width;
      p.height = g.height;
      p.x = c * (g.width + g.mullion_x);
      p.y = r * (g.height + g.mullion_y);
      const auto it = drivers.find({i, j});
      if (it == drivers.end()) {
        ++undriven;
        p.origin = fmt::format("screen i={} j={}, driven by no process of the file", i, j);
      } else {
        const Driver& dr = it->second;
        p.origin = fmt::format("screen i={} j={} of processes[{}] on {}{}", i, j, dr.process,
                               dr.host, dr.display.empty() ? "" : ", X display " + dr.display);
      }
      d.displays.push_back(p);
    }
  }
  if (undriven > 0) {
    d.notes.push_back(fmt::format(
        "{} of the {} displays are on screens no process drives: imported where the grid puts "
        "them",
        undriven, columns * rows));
  }
  if (d.hosts.empty()) {
    d.notes.push_back("no process drives surfaces[0]: one pipeserver per display, no hosts");
  }
  return d;
}

}  // namespace l2
