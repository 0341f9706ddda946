// What the balancing tests compare: a run whose layout changes from frame to frame against a
// run of one layout, display by display, byte for byte. A pipeserver stamps its frame into its
// stamp strip, which no display shows; one whose framebuffer has no room for a strip marks its
// first tile's first pixel instead, and those marks (which move with the layout) are set aside.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "balance/control_messages.hpp"
#include "image/png_io.hpp"
#include "l2wall/frame_stamp.hpp"
#include "tilelayout/tile_layout.hpp"
#include "wall_run.hpp"

namespace l2::testing_support {

using Spot = std::pair<int, int>;

// Where the first tile of each pipeserver that has tiles in `layout` starts on display `d`: what
// moves when a layout changes.
inline std::vector<Spot> first_tiles_on(const TileLayout& layout, int d) {
  std::vector<Spot> spots;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    if (plan.tiles.empty()) continue;
    const DisplayTile& t = plan.tiles.front().tile;
    if (t.display == d) spots.emplace_back(t.on_display.x, t.on_display.y);
  }
  return spots;
}

// Where a pipeserver without a stamp strip in `layout` marks display `d` with its stamp.
inline std::vector<Spot> stamps_on(const TileLayout& layout, int d) {
  std::vector<Spot> spots;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    if (plan.tiles.empty() || plan.has_stamp_strip()) continue;
    const DisplayTile& t = plan.tiles.front().tile;
    if (t.display == d) spots.emplace_back(t.on_display.x, t.on_display.y);
  }
  return spots;
}

inline int stamp_at(const RgbImage& image, const Spot& s) {
  const Rgb px = image.at(s.first, s.second);
  const std::uint8_t bytes[3] = {px.r, px.g, px.b};
  return decode_stamp(bytes);
}

// The layouts a balanced run's pipeservers rendered each frame in, as it wrote them
// (OUT/layouts.txt, frame k on line k+1).
inline std::vector<TileLayout> layouts_of(const WallRun& run, const Wall& wall) {
  std::vector<TileLayout> layouts;
  std::istringstream in(slurp(run.out() / "layouts.txt"));
  for (std::string line; std::getline(in, line);) {
    const LayoutMessage m = decode_layout(line);
    EXPECT_EQ(m.frame, static_cast<int>(layouts.size()));
    layouts.push_back(plan_from_message(wall, m));
  }
  return layouts;
}

// Every display of the kept frames `frames` of `other` (rendered in `layouts[k]`) equals the
// one of `fixed` (rendered in `fixed_layout`) byte for byte, the marks of pipeservers without a
// stamp strip aside, and each such mark says its frame.
inline void expect_displays_equal_stamps_aside(const WallRun& fixed, const TileLayout& fixed_layout,
                                               const WallRun& other,
                                               const std::vector<TileLayout>& layouts,
                                               const std::vector<int>& frames) {
  const int displays = static_cast<int>(fixed_layout.wall.displays.size());
  for (int k : frames) {
    ASSERT_LT(static_cast<std::size_t>(k), layouts.size());
    const TileLayout& now = layouts[static_cast<std::size_t>(k)];
    for (int d = 0; d < displays; ++d) {
      const auto file =
          std::filesystem::path(fmt::format("frame-{}", k)) / fmt::format("display-{}.png", d);
      const RgbImage a = read_png(fixed.out() / file);
      const RgbImage b = read_png(other.out() / file);
      ASSERT_EQ(a.width(), b.width());
      ASSERT_EQ(a.height(), b.height());
      std::vector<Spot> skip = stamps_on(fixed_layout, d);
      for (const Spot& s : skip) EXPECT_EQ(stamp_at(a, s), k) << file;
      for (const Spot& s : stamps_on(now, d)) {
        EXPECT_EQ(stamp_at(b, s), k) << file;
        skip.push_back(s);
      }
      long differ = 0;
      for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
          if (std::find(skip.begin(), skip.end(), Spot{x, y}) != skip.end()) continue;
          differ += !(a.at(x, y) == b.at(x, y));
        }
      }
      EXPECT_EQ(differ, 0) << file;
    }
  }
}

}  // namespace l2::testing_support
