// `tilelayout import FILE`: a wall described in Tide's, SAGE2's or nDisplay's configuration,
// printed (or written) as the equivalent wall file, and the hosts it names as an mpirun
// hostfile. The files are read and written here; what they mean is l2_wall_import's.
#pragma once

#include <optional>
#include <string>

#include "tilelayout/wall_import.hpp"

namespace l2 {

struct ImportOptions {
  std::string file;
  std::optional<ImportFormat> format;
  std::string out;       // empty: the wall file on stdout
  std::string hostfile;  // empty: none written
};

// Exit status: 0 written, 1 the file cannot be read or imported (one line on stderr), 3 an
// output file could not be written.
int run_import(const ImportOptions& options);

}  // namespace l2
