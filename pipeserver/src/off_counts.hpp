// An OFF file's vertex and face counts against the file's size. Assimp allocates what the header
// declares before it reads a line: a 309-byte file declaring a billion vertices drove a
// pipeserver past 6 GB until the kernel killed it.
#pragma once

#include <filesystem>

namespace l2::detail {

// Does nothing for a file Assimp does not read as OFF (neither "off" in its first three bytes,
// any case, nor the extension .off) or whose header Assimp refuses itself. Throws
// std::runtime_error ("FILE: declares 1000000000 vertices and 1000000000 faces, more than the
// rest of the file can hold (a line each)").
void check_off_counts(const std::filesystem::path& path);

}  // namespace l2::detail
