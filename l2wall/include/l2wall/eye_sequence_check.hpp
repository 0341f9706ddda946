// The proof that an active (frame-sequential) stereo wall shows both eyes of every frame
// together: its frames are eye frames (tilelayout/wall.hpp's frame_eye: 2k the left eye of
// application frame k, 2k+1 its right), so in every refresh each display must show either the
// eye frame it showed in the refresh before or the next one. Then application frame k's left eye
// is followed, in the very next refresh that changes the display, by its own right eye, and that
// by frame k+1's left: no display ever shows a left and a right of different frames one after
// the other, and none skips an eye. Fed the frame stamps every display shows in each refresh (the
// same records as swap_lock_check.hpp). Owns, per display, the eye frame it showed last and how
// many pairs it completed. Pure logic, so a broken sequence can be fed to it directly.
#pragma once

#include <cstdint>
#include <map>
#include <span>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"

namespace l2 {

class EyeSequenceCheck {
 public:
  // One line naming refresh, display and rank when a display shows an eye frame that is neither
  // the one it showed in the refresh before nor the next; the refresh is counted otherwise.
  Status check(std::uint64_t refresh, std::span<const DisplayShown> shown);

  // Pairs (a left eye then its own right in the next change) that every display showed: the
  // fewest of any display.
  int pairs() const;
  int displays() const { return static_cast<int>(last_.size()); }
  // Refreshes, summed over displays, in which a display kept the eye frame it showed before
  // (no new eye frame was ready): a frame-sequential projector would show that eye again.
  std::uint64_t held() const { return held_; }

 private:
  struct Seen {
    int frame = -1;  // the eye frame it showed last; -1: none yet
    int pairs = 0;
  };
  std::map<int, Seen> last_;  // by display id
  std::uint64_t held_ = 0;
};

}  // namespace l2
