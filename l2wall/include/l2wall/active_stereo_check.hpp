// The proof that an active (frame-sequential) stereo wall alternates strictly: in every refresh
// every display shows the eye of the refresh's parity (even refreshes the left eye, odd the
// right: the glasses switch every refresh) of one application frame, the same frame on every
// display (one swap group, one emitter), and a right-eye refresh shows the frame of the left-eye
// refresh before it: a pair changes only at a left-eye refresh, so no eye is ever shown alone or
// with the other eye of a different frame. Before the first pair every display shows nothing.
// Fed the frame stamps every display shows in each refresh after the quad buffer
// (quad_buffer.hpp: DisplayShown::frame the eye frame, 2k + eye, -1 none). Owns, per display,
// the application frame it showed last and the pairs it showed, new and repeated. Pure logic, so
// a broken sequence can be fed to it directly. Also owns stereo-refreshes.csv's text: each
// refresh's eye and frame, at most `max_rows` rows so a long run's record stays bounded.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "base/result.hpp"
#include "l2wall/column_records.hpp"

namespace l2 {

inline constexpr std::size_t kMaxStereoRefreshRows = std::size_t{1} << 20;

class ActiveStereoCheck {
 public:
  explicit ActiveStereoCheck(std::size_t max_rows = kMaxStereoRefreshRows) : max_rows_(max_rows) {}

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
  // `refresh,eye,frame` per refresh checked (`none` and no frame before the first pair).
  const std::string& csv() const { return csv_; }
  // Whether refreshes were checked past the rows csv() holds.
  bool csv_cut() const { return refreshes_ > max_rows_; }

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
  std::size_t max_rows_;
  std::string csv_ = "refresh,eye,frame\n";
};

}  // namespace l2
