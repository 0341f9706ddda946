#include "desktop_regions.hpp"

#include <algorithm>

namespace l2 {

std::vector<Rect> desktop_regions(const std::vector<Rect>& tiles,
                                  const std::vector<WindowPlace>& shown,
                                  const std::vector<DesktopWindow>& windows, int width,
                                  int height) {
  std::vector<Rect> regions;
  for (const WindowPlace& place : shown) {
    const auto w = std::find_if(windows.begin(), windows.end(),
                                [&place](const DesktopWindow& d) { return d.id == place.id; });
    if (w == windows.end()) continue;
    const Rect& at = place.on_canvas;
    const Canvas own{at.w, at.h};
    const SourceView view = movie_view(width, height, own, w->fit);
    for (const Rect& tile : tiles) {
      const Rect part = intersect(tile, at);
      if (part.empty()) continue;
      // The part as the window's own canvas has it, as the pipeserver's window draws it.
      const Rect moved{part.x - at.x, part.y - at.y, part.w, part.h};
      const Rect r = sampled_source(view, width, height, own, moved);
      if (!r.empty() && std::find(regions.begin(), regions.end(), r) == regions.end())
        regions.push_back(r);
    }
  }
  return regions;
}

}  // namespace l2
