// Reads the configuration, imports it, writes the wall file and the hostfile, and says what the
// import could not carry (stderr when the wall file goes to stdout, so the two never mix).
#include "import_command.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// The reason is the system's (open(2) sets errno for the stream): "Not a directory" and so on.
void write_text(const std::string& path, const std::string& text) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path, errno ? std::strerror(errno) : "cannot open it"));
  }
  out << text;
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}: writing failed", path));
}

}  // namespace

int run_import(const ImportOptions& options) {
  ImportedWall wall;
  try {
    std::ifstream in(options.file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw LayoutError(fmt::format("{}: cannot be read", options.file));
    wall = import_wall(text.str(), options.file, options.format);
    if (!options.hostfile.empty() && wall.hosts.empty()) {
      throw LayoutError(
          fmt::format("{}: names no hosts, so there is no hostfile to write", options.file));
    }
  } catch (const LayoutError& e) {
    std::cerr << "tilelayout import: " << e.what() << "\n";
    return 1;
  }
  std::ostream& said = options.out.empty() ? std::cerr : std::cout;
  try {
    if (options.out.empty()) {
      std::cout << wall.toml;
    } else {
      write_text(options.out, wall.toml);
      said << "wrote " << options.out << "\n";
    }
    if (!options.hostfile.empty()) {
      write_text(options.hostfile, mpi_hostfile(wall.hosts, wall.display_count));
      said << "wrote " << options.hostfile << " (mpirun --hostfile)\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "tilelayout import: " << e.what() << "\n";
    return 3;
  }
  for (const std::string& note : wall.notes) said << "note: " << note << "\n";
  return 0;
}

}  // namespace l2
