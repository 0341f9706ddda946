#include "verify/check_picture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "image/legend.hpp"

namespace l2 {
namespace {

std::vector<LegendEntry> legend(const DisplayCheck& d) {
  return {{fmt::format("right {} (the display, dimmed)", d.right), {64, 64, 64}},
          {fmt::format("missing {}", d.missing), kMissingColour},
          {fmt::format("misplaced {}", d.misplaced), kMisplacedColour},
          {fmt::format("written twice {} (yellow where right in the end)", d.written_twice),
           kTwiceColour},
          {fmt::format("behind mullions {} (in the margin)", d.behind_mullions), kMullionColour},
          {"misplaced runs are framed", kRunMarker}};
}

Rgb kind_colour(PixelKind kind, Rgb dimmed) {
  switch (kind) {
    case PixelKind::Missing:
      return kMissingColour;
    case PixelKind::Misplaced:
      return kMisplacedColour;
    case PixelKind::Twice:
      return kTwiceColour;
    default:
      return dimmed;
  }
}

void draw_display(const DisplayCheck& d, const RgbImage& shown, RgbImage& picture) {
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      const Rgb c = shown.at(x, y);
      const Rgb dim{static_cast<std::uint8_t>(c.r / 4), static_cast<std::uint8_t>(c.g / 4),
                    static_cast<std::uint8_t>(c.b / 4)};
      picture.set(x, y, kind_colour(d.kinds[static_cast<std::size_t>(y) * d.width + x], dim));
    }
  }
}

// A run past the right edge is drawn on its row in the right margin, one past the bottom edge
// on the margin row as far below as it is (the last margin row for farther ones).
void draw_mullion_runs(const DisplayCheck& d, std::span<const MullionRun> runs, int margin,
                       RgbImage& picture) {
  for (const MullionRun& r : runs) {
    if (r.start.display != d.display) continue;
    const int y = std::min(r.start.y, d.height + margin - 1);
    const int x0 = std::min(r.start.x, d.width + margin);
    const int x1 = std::min(r.start.x + r.width, d.width + margin);
    if (x1 > x0) picture.fill_rect(x0, y, x1 - x0, 1, kMullionColour);
  }
}

// A square outline around every misplaced run, `reach` pixels out, so that even a run of one
// pixel is found when the picture is viewed scaled down (as the golden diff pictures mark);
// drawn over right pixels and the empty margin only, never over a wrong pixel.
void mark_runs(const DisplayCheck& d, std::span<const MisplacedRun> runs, RgbImage& picture) {
  const int reach = std::max(6, std::max(d.width, d.height) / 128);
  auto mark = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= picture.width() || y >= picture.height()) return;
    if (x < d.width && y < d.height) {
      const PixelKind k = d.kinds[static_cast<std::size_t>(y) * d.width + x];
      if (k != PixelKind::Right && k != PixelKind::Unplanned) return;
    } else if (picture.at(x, y) != kMarginColour) {
      return;  // a pixel that fell behind a mullion
    }
    picture.set(x, y, kRunMarker);
  };
  int marked = 0;
  for (const MisplacedRun& r : runs) {
    if (r.landed.display != d.display) continue;
    if (++marked > kMarkedRuns) return;
    const int x0 = r.landed.x - reach, y0 = r.landed.y - reach;
    const int x1 = r.landed.x + r.width - 1 + reach, y1 = r.landed.y + r.rows - 1 + reach;
    for (int x = x0; x <= x1; ++x) {
      mark(x, y0);
      mark(x, y1);
    }
    for (int y = y0; y <= y1; ++y) {
      mark(x0, y);
      mark(x1, y);
    }
  }
}

}  // namespace

int check_margin(const DisplayCheck& d) {
  return std::max(8, std::max(d.width, d.height) / 100);
}

RgbImage check_picture(const RoutingCheck& check, std::size_t index, const RgbImage& shown) {
  const DisplayCheck& d = check.displays[index];
  const int margin = check_margin(d);
  RgbImage picture(d.width + margin, d.height + margin, kMarginColour);
  draw_display(d, shown, picture);
  draw_mullion_runs(d, check.mullion_runs, margin, picture);
  mark_runs(d, check.misplaced, picture);
  return with_legend(picture, legend(d));
}

}  // namespace l2
