// Reads the configuration, imports it, writes the wall file and the hostfile (an MPCDI archive's
// maps beside the wall file), and says what the import could not carry (stderr when the wall
// file goes to stdout, so the two never mix).
#include "import_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "image/grey_resample.hpp"
#include "image/png_io.hpp"
#include "mpcdi_archive.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxMpcdiXmlBytes = 16 << 20;  // as import_mpcdi takes it
constexpr int kMaxImportedMapSide = 4096;              // a display is at most 4095 a side

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

// Where an MPCDI archive's maps go, relative to the wall file: "WALL-STEM.calibration".
std::string maps_folder(const ImportOptions& o) {
  return fs::path(o.out.empty() ? o.file : o.out).stem().string() + ".calibration";
}

ImportedWall import_archive(std::string bytes, const ImportOptions& o,
                            std::unique_ptr<MpcdiArchive>& archive) {
  archive = std::make_unique<MpcdiArchive>(std::move(bytes), o.file);
  const std::vector<std::string>& entries = archive->entries();
  if (std::find(entries.begin(), entries.end(), "mpcdi.xml") == entries.end()) {
    throw LayoutError(fmt::format(
        "{}: mpcdi.xml: not in the archive (an MPCDI file describes its displays there)", o.file));
  }
  return import_mpcdi(archive->read("mpcdi.xml", kMaxMpcdiXmlBytes), entries, o.file,
                      {maps_folder(o), o.display_gamma.value_or(2.2)});
}

// An extracted alpha or beta map of another size than its display's, grey as the wall takes its
// maps, resampled to the display's size in its place (a calibration's maps may be coarser than
// its projectors' rasters); a note says so. A colour map is left for the wall to refuse.
void fit_map(const fs::path& path, const ExtractedFile& f, const std::string& file,
             std::vector<std::string>& notes) {
  PictureSource source;
  RgbImage map;
  try {
    map = read_png(path, &source, [&](int width, int height) {
      if (width > kMaxImportedMapSide || height > kMaxImportedMapSide) {
        throw LayoutError(fmt::format("{}x{}, larger than any projector's map (at most {} a side)",
                                      width, height, kMaxImportedMapSide));
      }
    });
  } catch (const std::runtime_error& e) {
    throw LayoutError(fmt::format("{}: {}: {}", file, f.entry, e.what()));
  }
  if (source.format != "png" || source.colour_channels != 1) return;
  if (map.width() == f.width && map.height() == f.height) return;
  std::vector<std::uint8_t> grey(static_cast<std::size_t>(map.width()) * map.height());
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      grey[static_cast<std::size_t>(y) * map.width() + x] = map.at(x, y).r;
  write_text(path.string(),
             encode_grey_png(f.width, f.height,
                             resample_grey(grey, map.width(), map.height(), f.width, f.height)));
  notes.push_back(fmt::format("{}: {}x{}, resampled (bilinear) to its display's {}x{} as {}",
                              f.entry, map.width(), map.height(), f.width, f.height, f.path));
}

// Extracts the maps beside the wall file `o.out` (resampling those of another size than their
// display's), then reads the wall with them as every program will: a map the wall cannot take
// is refused here, and what was extracted removed again.
void extract_maps(ImportedWall& wall, const MpcdiArchive& archive, const ImportOptions& o) {
  const fs::path base = fs::path(o.out).parent_path();
  std::vector<fs::path> written;
  try {
    fs::create_directories(base / maps_folder(o));
    for (const ExtractedFile& f : wall.files) {
      const std::string bytes = archive.read(f.entry);
      written.push_back(base / f.path);
      write_text(written.back().string(), bytes);
      if (f.width > 0) fit_map(written.back(), f, o.file, wall.notes);
    }
    try {
      parse_wall(wall.toml, o.out);
    } catch (const LayoutError& e) {
      throw LayoutError(
          fmt::format("{}: the imported wall does not load with its maps: {}", o.file, e.what()));
    }
  } catch (const std::runtime_error&) {
    std::error_code ignored;
    for (const fs::path& p : written) fs::remove(p, ignored);
    fs::remove(base / maps_folder(o), ignored);  // only when empty: not a folder of the user's
    throw;
  }
}

}  // namespace

int run_import(const ImportOptions& options) {
  ImportedWall wall;
  std::unique_ptr<MpcdiArchive> archive;
  try {
    std::ifstream in(options.file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw LayoutError(fmt::format("{}: cannot be read", options.file));
    const bool mpcdi =
        options.format ? *options.format == ImportFormat::Mpcdi : looks_like_zip(text.view());
    if (options.display_gamma && !mpcdi) {
      std::cerr << "tilelayout import: --display-gamma is for MPCDI calibrations, and "
                << options.file << " is not one\n";
      return 2;
    }
    if (mpcdi) {
      wall = import_archive(std::move(text).str(), options, archive);
    } else {
      wall = import_wall(text.str(), options.file, options.format);
    }
    if (!options.hostfile.empty() && wall.hosts.empty()) {
      throw LayoutError(
          fmt::format("{}: names no hosts, so there is no hostfile to write", options.file));
    }
    if (archive && !options.out.empty()) extract_maps(wall, *archive, options);
  } catch (const LayoutError& e) {
    std::cerr << "tilelayout import: " << e.what() << "\n";
    return 1;
  } catch (const std::runtime_error& e) {
    std::cerr << "tilelayout import: " << e.what() << "\n";
    return 3;
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
  if (archive && options.out.empty() && !wall.files.empty()) {
    said << fmt::format(
        "note: the {} files of its maps are not extracted without --write WALL, which puts "
        "them in WALL's folder, in WALL-STEM.calibration/\n",
        wall.files.size());
  } else if (archive) {
    said << fmt::format("wrote {} files of its maps into {}\n", wall.files.size(),
                        (fs::path(options.out).parent_path() / maps_folder(options)).string());
  }
  for (const std::string& note : wall.notes) said << "note: " << note << "\n";
  return 0;
}

}  // namespace l2
