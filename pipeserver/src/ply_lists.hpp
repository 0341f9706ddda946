// A PLY body's list lengths against the file's size. Assimp sizes each list by the length the
// body declares before it reads the list: a face declaring 100 million vertex indices in a file
// of 150 bytes took 800 MB, one declaring 4 billion ended in a bare "std::bad_alloc".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace l2::detail {

struct PlyProperty {
  std::string name, type, count_type;  // count_type: a list's length's
  std::uintmax_t size = 0;             // binary bytes of a value (0: a type Assimp refuses)
  std::uintmax_t count_size = 0;       // binary bytes of a list's length
  bool list = false;
};

struct PlyElement {
  std::string name;
  std::uintmax_t count = 0, min_bytes = 0;  // the fewest bytes one entry can take
  int line = 0;                             // of the header
  std::vector<PlyProperty> properties;
};

struct PlyBody {
  const std::filesystem::path& path;
  const std::string& text;  // the whole file
  std::size_t start = 0;    // after end_header
  bool big_endian = false;
};

// Each list of each entry, in order: its length may not exceed what the rest of the file can
// hold (in binary, its values' bytes; in ASCII, two bytes a value, as Assimp reads an entry's
// values from its one line). Throws std::runtime_error ("FILE: face 0: list 'vertex_indices'
// declares 100000000 values, more than the rest of the file can hold"). Stops quietly where
// the body ends early or holds what Assimp refuses itself.
void check_binary_lists(const PlyBody& body, const std::vector<PlyElement>& elements);
void check_ascii_lists(const PlyBody& body, const std::vector<PlyElement>& elements);

}  // namespace l2::detail
