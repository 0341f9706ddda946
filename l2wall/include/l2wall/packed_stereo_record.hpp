// The proof that a packed stereo wall (side-by-side, top-bottom: tilelayout/wall.hpp's
// display_parts) shows both eyes of each frame together, from the records the board columns
// send every refresh (the same as swap_lock_check.hpp's): each display's frame stamp and the
// oldest stamp among the pipeservers' strips routed into the picture it shows. A packed
// display's left (top) half is rendered with the left eye's camera and the other half with the
// right's, each half by the pipeservers the plan gives its tiles; when the oldest stamp is the
// display's frame, every part of both halves is of that frame, so both eyes of it are shown in
// the same refresh. Counts, per display, the frames it showed, for the run's summary. Owns, per
// display, the frame it showed last and how many it has shown. Pure logic, so a violation can be
// fed to it directly.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class PackedStereoRecord {
 public:
  // A wall of `wall`'s displays; `wall` packed (side-by-side or top-bottom).
  explicit PackedStereoRecord(const Wall& wall);

  // One refresh's records. One line naming refresh, display and rank when a display shows parts
  // of an older frame than its stamp says (its halves could show two frames' eyes); displays
  // without a frame yet are not checked. A display showing another frame than before has shown
  // one more.
  Status check(std::uint64_t refresh, std::span<const DisplayShown> shown);
  // The fewest frames any display showed (each with both eyes in its halves).
  int fewest_frames() const;
  // The summary's line, e.g. "packed stereo (side-by-side): each of 2 display(s) showed both
  // eyes of each of its frames in its two halves in the same refresh (left half: left eye, right
  // half: right eye; every strip of it stamped with that frame), at least 10 frame(s) each, in
  // all 12 refreshes".
  std::string summary_line(std::uint64_t refreshes) const;

 private:
  StereoMode mode_;
  std::vector<int> last_;    // by display id: the frame it showed last, -1: none yet
  std::vector<int> frames_;  // by display id: how many frames it showed
};

}  // namespace l2
