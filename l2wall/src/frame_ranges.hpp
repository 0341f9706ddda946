// Frame numbers as a summary line lists them: a run of hundreds is one range, not kilobytes.
#pragma once

#include <string>
#include <vector>

namespace l2 {

// Ascending `frames` as ranges: {0, 1, 2, 3, 7, 9, 10} is "0-3, 7, 9-10"; none is "".
std::string frame_ranges(const std::vector<int>& frames);

}  // namespace l2
