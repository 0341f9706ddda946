// A PLY header's element counts against the file's size. Assimp reserves memory for what a
// header declares before reading the body, so a count of 9e18 in a file of a few bytes asked
// for tens of gigabytes: refused here first, naming the element and the header line.
#pragma once

#include <filesystem>

namespace l2::detail {

// Does nothing for a file that does not start with "ply". Throws std::runtime_error
// ("FILE:LINE: element 'vertex' declares N entries, more than the rest of the file can hold").
void check_ply_counts(const std::filesystem::path& path);

}  // namespace l2::detail
