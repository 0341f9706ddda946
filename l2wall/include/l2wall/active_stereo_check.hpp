// The proof that an active (frame-sequential) stereo wall alternates strictly: in every refresh
// every display shows the eye of the refresh's parity (even refreshes the left eye, odd the
// right: the glasses switch every refresh) of one application frame, the same frame on every
// display (one swap group, one emitter), and a right-eye refresh shows the frame of the left-eye
// refresh before it: a pair changes only at a left-eye refresh, so no eye is ever shown alone or
// with the other eye of a different frame. Before the first pair every display shows nothing.
// Fed the frame stamps every display shows in each refresh after the quad buffer
// (quad_buffer.hpp: DisplayShown::frame the eye frame, 2k + eye, -1 none). Owns, per display,
// the application frame it showed last and the pairs it showed, new and repeated. Pure logic, so
// a broken sequence can be fed to it directly.
#pragma once

#include <cstdint>
#include <map>
#include <span>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"

namespace l2 {

class ActiveStereoCheck {
 public:
  // One line naming refresh, display and rank at the first display that breaks the rule; the
  // refresh is counted otherwise.
  Status check(std::uint64_t refresh, std::span<const DisplayShown> shown);

  std::uint64_t refreshes() const { return refreshes_; }
  // The refresh that showed the first pair; -1 before.
  std::int64_t first_pair() const { return first_pair_; }
  // Pairs shown (a left-eye refresh and the right-eye one after it) by the display that showed
  // the fewest new ones, and how many of those repeated the pair before (no new pair ready).
  std::uint64_t pairs_shown() const;
  std::uint64_t pairs_repeated() const;

 private:
  struct Seen {
    int frame = -1;  // the application frame it showed last; -1: none yet
    std::uint64_t pairs = 0, repeated = 0;
  };
  Status check_display(std::uint64_t refresh, const DisplayShown& s, int group_frame);
  const Seen& fewest_new() const;

  std::map<int, Seen> last_;  // by display id
  std::uint64_t refreshes_ = 0;
  std::int64_t first_pair_ = -1;
};

}  // namespace l2
