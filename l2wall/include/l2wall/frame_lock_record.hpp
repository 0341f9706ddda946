// What a live run proves about frame lock (docs/wall-file.md, [displays]): at every refresh of
// the DVI path, the frame each display shows by its own refresh clock (DisplayClocks), from the
// frames the columns' displays hold in lock; the summary's count of refreshes per swap group whose
// displays showed different frames, and frame-lock.csv, per refresh each display's frame counter
// and the frame it showed.
//
// Owns: the display clocks and the CSV text (its rows bounded: a long run keeps its first ones).
// Pure logic: the DVI path feeds it what the columns saw and writes nothing itself.
#pragma once

#include <span>
#include <string>

#include "l2wall/column_records.hpp"
#include "lightning2_emu/display_clocks.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The most cells frame-lock.csv holds; the rows past it are counted, not written.
inline constexpr std::size_t kMaxFrameLockCells = std::size_t{1} << 22;

class FrameLockRecord {
 public:
  // The wall's displays' clocks (Display::clock_ppm, FrameLockSpec::house_sync) and `groups`;
  // frame-lock.csv holds the rows of at most `max_cells` cells.
  FrameLockRecord(const Wall& wall, std::vector<SwapGroup> groups,
                  std::size_t max_cells = kMaxFrameLockCells);

  // One refresh: `shown`, the frame each display holds as swapped in lock (displays missing: -1).
  void refresh(std::span<const DisplayShown> shown);

  const DisplayClocks& clocks() const { return clocks_; }
  // The frame display `id` shows by its own clock this refresh.
  int shown(int id) const { return clocks_.shown().at(static_cast<std::size_t>(id)); }
  // This refresh, a line per display: "display D: frame F, counter C" (F -1: none yet), after
  // "refresh S".
  std::string shown_lines() const;
  // "frame lock: ..." lines for the summary.
  std::string summary_lines() const;
  // frame-lock.csv: a header, then one row per refresh: refresh, each display's counter and
  // frame (counter_D, frame_D), and the groups mismatched in it (group numbers, space separated).
  const std::string& csv() const { return csv_; }

 private:
  void add_row();

  DisplayClocks clocks_;
  std::vector<int> locked_;  // by display id, this refresh
  std::vector<std::uint64_t> mismatched_before_;
  std::string csv_;
  std::size_t rows_ = 0, max_rows_ = 0;
};

}  // namespace l2
