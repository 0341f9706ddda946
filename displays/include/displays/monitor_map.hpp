// Which monitor each output display goes fullscreen on (--show monitors). The wall file names a
// monitor per display (`monitor`: the name GLFW reports, or its index in GLFW's list); this is
// the pure decision, so every refusal and its message is tested without a screen.
#pragma once

#include <string>
#include <vector>

#include "tilelayout/wall.hpp"

namespace l2 {

struct MonitorInfo {
  std::string name;           // as GLFW reports it (the RandR output name on X11, e.g. "DP-1")
  int x = 0, y = 0;           // position on the virtual desktop
  int width = 0, height = 0;  // current video mode
};

// "1 monitor: [0] "screen" 1600x1200 at (0,0)" — the list every refusal ends with.
std::string describe_monitors(const std::vector<MonitorInfo>& monitors);

// For each display (in wall order), the index into `monitors` it is shown on. Throws
// DisplayError when there are fewer monitors than displays, a display has no monitor, names one
// that does not exist, or shares its monitor with another display.
std::vector<int> map_displays_to_monitors(const Wall& wall,
                                          const std::vector<MonitorInfo>& monitors);

}  // namespace l2
