// `tilelayout import FILE`: a wall described in Tide's, SAGE2's or nDisplay's configuration or
// in an MPCDI calibration, printed (or written) as the equivalent wall file, the hosts it names
// as an mpirun hostfile, an MPCDI archive's maps extracted beside the wall file. The files are
// read and written here; what they mean is l2_wall_import's.
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
  // MPCDI: the projectors' gamma (alpha_gamma = it / the alpha map's gammaEmbedded); absent 2.2.
  std::optional<double> display_gamma;
};

// Exit status: 0 written, 1 the file cannot be read or imported (one line on stderr), 2
// --display-gamma for a file that is not MPCDI, 3 an output file could not be written.
int run_import(const ImportOptions& options);

}  // namespace l2
