#include "displays/monitor_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>

#include "command_line/printable.hpp"
#include "displays/display_error.hpp"

namespace l2 {

namespace {

std::string wall_name(const Wall& wall) {
  if (!wall.source.empty()) return printable(wall.source.string());
  return wall.name.empty() ? std::string("wall") : fmt::format("wall '{}'", printable(wall.name));
}

std::optional<int> as_index(const std::string& text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// A name wins over an index, so a monitor really called "1" is still reachable by name.
std::optional<int> find_monitor(const std::string& wanted,
                                const std::vector<MonitorInfo>& monitors) {
  for (std::size_t i = 0; i < monitors.size(); ++i) {
    if (monitors[i].name == wanted) return static_cast<int>(i);
  }
  const std::optional<int> index = as_index(wanted);
  if (index && *index >= 0 && *index < static_cast<int>(monitors.size())) return index;
  return std::nullopt;
}

}  // namespace

std::string describe_monitors(const std::vector<MonitorInfo>& monitors) {
  std::string text = fmt::format("{} monitor{}", monitors.size(), monitors.size() == 1 ? "" : "s");
  for (std::size_t i = 0; i < monitors.size(); ++i) {
    const MonitorInfo& m = monitors[i];
    text += fmt::format("{} [{}] \"{}\" {}x{} at ({},{})", i == 0 ? ":" : ",", i, m.name, m.width,
                        m.height, m.x, m.y);
  }
  return text;
}

std::vector<int> map_displays_to_monitors(const Wall& wall,
                                          const std::vector<MonitorInfo>& monitors) {
  const std::string seen = "GLFW sees " + describe_monitors(monitors);
  if (monitors.size() < wall.displays.size()) {
    throw DisplayError(
        fmt::format("{}: --show monitors needs one monitor per display: {} displays"
                    ", but {}",
                    wall_name(wall), wall.displays.size(), seen));
  }
  std::vector<int> chosen;
  for (const Display& d : wall.displays) {
    if (d.monitor.empty()) {
      throw DisplayError(
          fmt::format("{}: display {} has no monitor (set its `monitor` to a name or index); {}",
                      wall_name(wall), d.id, seen));
    }
    const std::optional<int> m = find_monitor(d.monitor, monitors);
    if (!m) {
      throw DisplayError(fmt::format("{}: display {}: monitor \"{}\" not found; {}",
                                     wall_name(wall), d.id, d.monitor, seen));
    }
    const auto taken = std::find(chosen.begin(), chosen.end(), *m);
    if (taken != chosen.end()) {
      throw DisplayError(fmt::format("{}: displays {} and {} both use monitor [{}] \"{}\"; {}",
                                     wall_name(wall), wall.displays[taken - chosen.begin()].id,
                                     d.id, *m, monitors[*m].name, seen));
    }
    chosen.push_back(*m);
  }
  return chosen;
}

}  // namespace l2
