#include "verify/check_picture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "displays/bitmap_font.hpp"

namespace l2 {
namespace {

struct LegendEntry {
  Rgb colour;
  std::string text;
};

std::vector<LegendEntry> legend(const DisplayCheck& d) {
  return {{{64, 64, 64}, fmt::format("right {} (the display, dimmed)", d.right)},
          {kMissingColour, fmt::format("missing {}", d.missing)},
          {kMisplacedColour, fmt::format("misplaced {}", d.misplaced)},
          {kTwiceColour, fmt::format("written twice {}", d.written_twice)},
          {kMullionColour, fmt::format("behind mullions {} (in the margin)", d.behind_mullions)}};
}

int legend_scale(const DisplayCheck& d) {
  return std::max(1, std::max(d.width, d.height) / 640);
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

void draw_legend(const DisplayCheck& d, int top, RgbImage& picture) {
  const int s = legend_scale(d), line = (kGlyphHeight + 3) * s;
  int y = top + 2 * s;
  for (const LegendEntry& e : legend(d)) {
    picture.fill_rect(2 * s, y, kGlyphHeight * s, kGlyphHeight * s, e.colour);
    draw_text(picture, (kGlyphHeight + 5) * s, y, e.text, {230, 230, 230}, s);
    y += line;
  }
}

}  // namespace

int check_margin(const DisplayCheck& d) {
  return std::max(8, std::max(d.width, d.height) / 100);
}

RgbImage check_picture(const DisplayCheck& d, const RgbImage& shown,
                       std::span<const MullionRun> mullion_runs) {
  const int margin = check_margin(d), s = legend_scale(d);
  const std::vector<LegendEntry> entries = legend(d);
  int legend_width = 0;
  for (const LegendEntry& e : entries) {
    legend_width = std::max(legend_width, (kGlyphHeight + 7) * s + text_width(e.text, s));
  }
  const int legend_height = static_cast<int>(entries.size()) * (kGlyphHeight + 3) * s + 4 * s;
  RgbImage picture(std::max(d.width + margin, legend_width), d.height + margin + legend_height,
                   Rgb{});
  picture.fill_rect(0, 0, d.width + margin, d.height + margin, kMarginColour);
  draw_display(d, shown, picture);
  draw_mullion_runs(d, mullion_runs, margin, picture);
  draw_legend(d, d.height + margin, picture);
  return picture;
}

}  // namespace l2
