#include "frame_ranges.hpp"

#include <fmt/format.h>

namespace l2 {

std::string frame_ranges(const std::vector<int>& frames) {
  std::string out;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    out += fmt::format("{}{}", out.empty() ? "" : ", ", frames[i]);
    if (j > i) out += fmt::format("-{}", frames[j]);
    i = j + 1;
  }
  return out;
}

}  // namespace l2
