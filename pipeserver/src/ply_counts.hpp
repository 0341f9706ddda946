// A PLY header's element counts against the file's size. Assimp reserves memory for what a
// header declares before reading the body, so a count of 9e18 in a file of a few bytes asked
// for tens of gigabytes: refused here first, naming the element and the header line. So are a
// header cut short (Assimp waited for its end_header for ever) and lists longer than the rest of
// the file (ply_lists.hpp).
#pragma once

#include <filesystem>

namespace l2::detail {

enum class PlyFormat { none, ascii, binary };

// Does nothing for a file that does not start with "ply" (returns none). Throws
// std::runtime_error ("FILE:LINE: element 'vertex' declares N entries, more than the rest of the
// file can hold", "FILE: the PLY header ends without end_header (cut short?)", or a list's, as
// ply_lists.hpp says). Returns the format the header names: in an ASCII PLY a face with a vertex
// repeated in a row is a face line cut short, not a degenerate triangle (model_file.cpp).
PlyFormat check_ply_counts(const std::filesystem::path& path);

}  // namespace l2::detail
