// What a packed stereo wall (side-by-side, top-bottom: tilelayout/wall.hpp's display_parts)
// showed, from the frame stamps every display shows in each refresh (the records
// swap_lock_check.hpp reads). A packed display's two halves are one raster that swaps as one,
// routed as a mono display's tiles are: the frame its stamp says it shows is the frame of both
// its halves, the left (top) one rendered with the left eye's camera and the other with the
// right's. So both eyes of every frame a display shows are in its two halves in the same
// refresh; this counts, per display, the frames it showed, for the run's summary. Owns, per
// display, the frame it showed last and how many it has shown. Pure logic.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "l2wall/column_records.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class PackedStereoRecord {
 public:
  // A wall of `wall`'s displays; `wall` packed (side-by-side or top-bottom).
  explicit PackedStereoRecord(const Wall& wall);

  // One refresh's records: a display showing another frame than before has shown one more.
  void take(std::span<const DisplayShown> shown);
  // The fewest frames any display showed (each with both eyes in its halves).
  int fewest_frames() const;
  // The summary's line, e.g. "packed stereo (side-by-side): each of 2 display(s) showed both
  // eyes of each of its frames in its two halves in the same refresh (left half: left eye, right
  // half: right eye), at least 10 frame(s) each by their stamps, in all 24 refreshes".
  std::string summary_line(std::uint64_t refreshes) const;

 private:
  StereoMode mode_;
  std::vector<int> last_;    // by display id: the frame it showed last, -1: none yet
  std::vector<int> frames_;  // by display id: how many frames it showed
};

}  // namespace l2
