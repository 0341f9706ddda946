#include "l2wall/frame_lock_record.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {
namespace {

std::vector<int> ppm_of(const Wall& wall) {
  std::vector<int> ppm;
  for (const Display& d : wall.displays) ppm.push_back(d.clock_ppm);
  return ppm;
}

std::string csv_header(std::size_t displays) {
  std::string h = "refresh";
  for (std::size_t d = 0; d < displays; ++d) h += fmt::format(",counter_{0},frame_{0}", d);
  return h + ",mismatched_groups\n";
}

}  // namespace

FrameLockRecord::FrameLockRecord(const Wall& wall, std::vector<SwapGroup> groups,
                                 std::size_t max_cells)
    : clocks_(ppm_of(wall), std::move(groups), wall.frame_lock.house_sync),
      locked_(wall.displays.size(), -1),
      mismatched_before_(clocks_.groups().size(), 0),
      csv_(csv_header(wall.displays.size())),
      max_rows_(std::max<std::size_t>(1, max_cells / (2 * wall.displays.size() + 2))) {}

void FrameLockRecord::refresh(std::span<const DisplayShown> shown) {
  std::fill(locked_.begin(), locked_.end(), -1);
  for (const DisplayShown& s : shown) {
    if (s.display >= 0 && static_cast<std::size_t>(s.display) < locked_.size())
      locked_[static_cast<std::size_t>(s.display)] = s.frame;
  }
  clocks_.refresh(locked_);
  if (rows_ < max_rows_) add_row();
  ++rows_;
  mismatched_before_ = clocks_.mismatched();
}

void FrameLockRecord::add_row() {
  auto out = std::back_inserter(csv_);
  fmt::format_to(out, "{}", clocks_.refreshes() - 1);
  for (std::size_t d = 0; d < locked_.size(); ++d)
    fmt::format_to(out, ",{},{}", clocks_.counters()[d], clocks_.shown()[d]);
  csv_ += ',';
  const char* space = "";
  for (std::size_t g = 0; g < clocks_.groups().size(); ++g) {
    if (clocks_.mismatched()[g] == mismatched_before_[g]) continue;
    fmt::format_to(out, "{}{}", space, clocks_.groups()[g].id);
    space = " ";
  }
  csv_ += '\n';
}

std::string FrameLockRecord::shown_lines() const {
  std::string text = fmt::format("refresh {}\n", clocks_.refreshes() - 1);
  for (std::size_t d = 0; d < clocks_.shown().size(); ++d) {
    fmt::format_to(std::back_inserter(text), "display {}: frame {}, counter {}\n", d,
                   clocks_.shown()[d], clocks_.counters()[d]);
  }
  return text;
}

std::string FrameLockRecord::summary_lines() const {
  std::string counts;
  for (std::size_t g = 0; g < clocks_.groups().size(); ++g) {
    counts += fmt::format("{}group {}: {}", g ? ", " : "", clocks_.groups()[g].id,
                          clocks_.mismatched()[g]);
  }
  const std::string where =
      rows_ > max_rows_
          ? fmt::format("frame-lock.csv holds the first {} refreshes", max_rows_)
          : std::string("each display's frame counter and frame per refresh in frame-lock.csv");
  return fmt::format(
      "frame lock: {}: mismatched refreshes (a swap group's displays showing different frames) "
      "of {}: {}; {}\n",
      clocks_.house_sync() ? "house sync locks every display's clock"
                           : "display clocks run free (clock_ppm)",
      clocks_.refreshes(), counts, where);
}

}  // namespace l2
