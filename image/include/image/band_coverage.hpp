// Coverage of one band of display rows, from the rectangles the strips of a frame wrote (the
// emulator's router) or a frame's tiles cover (the compositing server): where the background
// must go, and nowhere else.
//
// Strips come in runs — a tile is the same source columns on consecutive scanlines going to the
// same display columns on consecutive rows — so the router records one rectangle per run, not
// one span per strip. Between two rows where some rectangle starts or ends, every row is
// covered alike: the sweep works out one such stretch of rows once (rectangles sorted by first
// column, keeping the two furthest ends seen) and multiplies. For the headline case that is a
// couple of stretches per band instead of one sort and sweep per row.
//
// Work is bounded by the per-row method's: a rectangle is looked at once per stretch it spans,
// and it spans no more stretches than it has rows.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace l2::coverage {

// Rows y0..y1-1, columns x0..x1-1 of a display, written by `input` during the current frame.
struct Area {
  std::uint16_t y0, y1, x0, x1, input;
};

struct CoverageCounts {
  std::uint64_t covered = 0;   // pixels at least one area covers
  std::uint64_t overdraw = 0;  // pixels two or more areas cover
};

// Scratch reused from frame to frame, so sweeping allocates nothing once warm.
struct CoverageScratch {
  std::vector<Area> by_start;  // areas by first row
  std::vector<Area> active;    // areas covering the current stretch
  std::vector<Area> sorted;    // the same by first column
  std::vector<std::uint16_t> cuts;
  struct Gap {
    int x0, x1;
  };
  std::vector<Gap> gaps;
};

// Sweeps rows row0..row1-1 of a display `width` pixels wide. Calls
// on_gaps(y0, y1, gaps) once per stretch of rows y0..y1-1 that has columns no area covers, with
// those columns as a list of CoverageScratch::Gap.
template <class OnGaps>
CoverageCounts sweep_coverage(const std::vector<Area>& areas, int row0, int row1, int width,
                              CoverageScratch& s, OnGaps&& on_gaps) {
  // The rows where the covering set changes cut the band into stretches.
  s.cuts.clear();
  s.cuts.push_back(static_cast<std::uint16_t>(row0));
  s.cuts.push_back(static_cast<std::uint16_t>(row1));
  for (const Area& a : areas) {
    s.cuts.push_back(a.y0);
    s.cuts.push_back(a.y1);
  }
  std::sort(s.cuts.begin(), s.cuts.end());
  s.cuts.erase(std::unique(s.cuts.begin(), s.cuts.end()), s.cuts.end());
  s.by_start.assign(areas.begin(), areas.end());
  std::sort(s.by_start.begin(), s.by_start.end(),
            [](const Area& a, const Area& b) { return a.y0 < b.y0; });

  CoverageCounts total;
  s.active.clear();
  std::size_t next = 0;  // first area of by_start not yet active
  for (std::size_t c = 0; c + 1 < s.cuts.size(); ++c) {
    const int y0 = s.cuts[c], y1 = s.cuts[c + 1];
    if (y0 < row0 || y1 > row1) continue;
    // Areas ending at or before y0 leave; those starting at y0 join.
    s.active.erase(
        std::remove_if(s.active.begin(), s.active.end(), [&](const Area& a) { return a.y1 <= y0; }),
        s.active.end());
    for (; next < s.by_start.size() && s.by_start[next].y0 <= y0; ++next) {
      if (s.by_start[next].y1 > y0) s.active.push_back(s.by_start[next]);
    }
    s.sorted.assign(s.active.begin(), s.active.end());
    std::sort(s.sorted.begin(), s.sorted.end(), [](const Area& a, const Area& b) {
      return a.x0 < b.x0 || (a.x0 == b.x0 && a.x1 < b.x1);
    });
    // Sweep by first column keeping the two furthest ends seen: a column is covered while the
    // furthest end lies beyond it and overdrawn while the second furthest does.
    s.gaps.clear();
    std::uint64_t covered = 0, overdraw = 0;
    int end1 = 0, end2 = 0, filled = 0;
    for (std::size_t k = 0;; ++k) {
      const bool done = k == s.sorted.size();
      const int start = done ? width : s.sorted[k].x0;
      if (start > filled) {
        const int gap_from = std::max(filled, end1);
        if (start > gap_from) s.gaps.push_back({gap_from, start});
        covered += static_cast<std::uint64_t>(std::max(0, std::min(end1, start) - filled));
        overdraw += static_cast<std::uint64_t>(std::max(0, std::min(end2, start) - filled));
        filled = start;
      }
      if (done) break;
      const int end = s.sorted[k].x1;
      if (end > end1) {
        end2 = end1;
        end1 = end;
      } else if (end > end2) {
        end2 = end;
      }
    }
    total.covered += covered * static_cast<std::uint64_t>(y1 - y0);
    total.overdraw += overdraw * static_cast<std::uint64_t>(y1 - y0);
    if (!s.gaps.empty()) on_gaps(y0, y1, s.gaps);
  }
  return total;
}

}  // namespace l2::coverage
