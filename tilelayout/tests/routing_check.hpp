// Test helper: reads scanned-out frames the way the emulator would (spec §3 parser) and counts,
// for every display pixel, how many COPY strip pixels land on it and whether each carries the
// test-pattern colour of exactly that pixel. Independent of the planner: it sees only frames.
#pragma once

#include <string>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct RoutingCheck {
  StripErrorCounts errors;
  long long copied = 0;         // strip pixels routed
  long long outside = 0;        // strip pixels landing outside their display
  long long wrong_colour = 0;   // strip pixels whose test pattern names another pixel
  long long wrong_parity = 0;   // COPY/SKIP headers with the other parity
  long long uncovered = 0;      // display pixels no strip wrote
  long long covered_twice = 0;  // display pixels more than one strip wrote
};

inline RoutingCheck check_routing(const Wall& wall, const std::vector<RgbImage>& frames,
                                  bool parity) {
  RoutingCheck out;
  std::vector<std::vector<int>> count;
  for (const Display& d : wall.displays) {
    count.emplace_back(static_cast<std::size_t>(d.width) * d.height, 0);
  }
  for (const RgbImage& frame : frames) {
    for (int y = 0; y < frame.height(); ++y) {
      const std::uint8_t* row = frame.row(y).data();
      parse_scanline(row, frame.width(), 3, out.errors, [&](const ParsedStrip& s) {
        if (s.header.frame != parity) ++out.wrong_parity;
        if (s.header.op != StripOp::Copy) return;
        if (s.header.display >= wall.displays.size()) {
          out.outside += s.length;
          return;
        }
        const Display& d = wall.displays[s.header.display];
        for (int i = 0; i < s.length; ++i) {
          const int dx = s.header.x + i, dy = s.header.y;
          ++out.copied;
          if (dx >= d.width || dy >= d.height) {
            ++out.outside;
            continue;
          }
          ++count[d.id][static_cast<std::size_t>(dy) * d.width + dx];
          const std::uint8_t* p = row + (s.source_x + i) * 3;
          const auto pos = test_pattern_position(d.id, Rgb{p[0], p[1], p[2]});
          if (!pos || pos->first != dx || pos->second != dy) ++out.wrong_colour;
        }
      });
    }
  }
  for (const auto& c : count) {
    for (int n : c) {
      out.uncovered += n == 0;
      out.covered_twice += n > 1;
    }
  }
  return out;
}

}  // namespace l2
