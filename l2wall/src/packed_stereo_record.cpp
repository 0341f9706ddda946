#include "l2wall/packed_stereo_record.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace l2 {

PackedStereoRecord::PackedStereoRecord(const Wall& wall)
    : mode_(wall.stereo.mode), last_(wall.displays.size(), -1), frames_(wall.displays.size(), 0) {}

Status PackedStereoRecord::check(std::uint64_t refresh, std::span<const DisplayShown> shown) {
  for (const DisplayShown& s : shown) {
    if (s.frame < 0) continue;
    if (s.oldest != s.frame) {
      return Failure{fmt::format(
          "packed stereo broken in refresh {}: display {} (rank {}) shows frame {}, but part of "
          "it frame {}: its halves could show the eyes of two frames",
          refresh, s.display, s.rank, s.frame, s.oldest)};
    }
    if (s.display < 0 || static_cast<std::size_t>(s.display) >= last_.size()) continue;
    int& last = last_[static_cast<std::size_t>(s.display)];
    if (s.frame == last) continue;
    last = s.frame;
    ++frames_[static_cast<std::size_t>(s.display)];
  }
  return {};
}

int PackedStereoRecord::fewest_frames() const {
  return frames_.empty() ? 0 : *std::min_element(frames_.begin(), frames_.end());
}

std::string PackedStereoRecord::summary_line(std::uint64_t refreshes) const {
  const bool side = mode_ == StereoMode::SideBySide;
  return fmt::format(
      "packed stereo ({}): each of {} display(s) showed both eyes of each of its frames in its "
      "two halves in the same refresh ({} half: left eye, {} half: right eye; every strip of it "
      "stamped with that frame), at least {} frame(s) each, in all {} refreshes\n",
      kStereoModeNames[static_cast<int>(mode_)], frames_.size(), side ? "left" : "top",
      side ? "right" : "bottom", fewest_frames(), refreshes);
}

}  // namespace l2
