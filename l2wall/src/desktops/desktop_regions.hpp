// Which desktop pixels a pipeserver samples through a session's vnc windows (docs/vnc.md,
// session_desktops.hpp): pure, tested without I/O.
#pragma once

#include <vector>

#include "balance/control_messages.hpp"
#include "pipeserver/picture_view.hpp"

namespace l2 {

// A vnc window of a desktop: its id and how the desktop is laid on it.
struct DesktopWindow {
  int id = 0;
  SourceFit fit = SourceFit::Fit;
};

// The desktop pixels a pipeserver whose tiles are `tiles` (canvas rectangles) samples through
// `windows` as `shown` places them, each window's part of each tile as the pipeserver's window
// draws it (picture_view.hpp): every rectangle once, empty parts left out. Pure.
std::vector<Rect> desktop_regions(const std::vector<Rect>& tiles,
                                  const std::vector<WindowPlace>& shown,
                                  const std::vector<DesktopWindow>& windows, int width, int height);

}  // namespace l2
