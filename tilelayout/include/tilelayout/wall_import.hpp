// Importing a wall described in another system's configuration: Tide's JSON configuration,
// SAGE2's wall configuration, Unreal Engine nDisplay's .ndisplay file and a VESA MPCDI
// calibration (its mpcdi.xml), each turned into the equivalent wall file (docs/wall-import.md
// says what maps to what). Pure: text in, text out; the tilelayout program reads and writes the
// files, and unpacks the MPCDI archive.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

enum class ImportFormat { Tide, Sage2, NDisplay, Mpcdi };

// "tide", "sage2", "ndisplay", "mpcdi": the names --format takes.
inline constexpr std::string_view kImportFormatNames[] = {"tide", "sage2", "ndisplay", "mpcdi"};

// A file of the imported archive the wall file names: `entry` (its name in the archive) is to be
// written to `path`, relative to the wall file's folder, as the wall file names it.
struct ExtractedFile {
  std::string entry;
  std::string path;
  // An alpha or beta map: the display's size, which the wall needs it at (a map of another size
  // is resampled as it is extracted); 0 for a warp.
  int width = 0, height = 0;
};

struct ImportedWall {
  ImportFormat format = ImportFormat::Tide;
  // The wall file: TOML that parse_wall reads and plan_layout plans, commented with where each
  // value came from.
  std::string toml;
  // One line each for what the wall file cannot carry or what had to be guessed (a projection
  // policy, a camera, stereo, a warp mesh); also written into `toml` as comments.
  std::vector<std::string> notes;
  // The host of every pipeserver, in pipeserver order (empty when the file names no hosts).
  std::vector<std::string> hosts;
  int display_count = 0;
  // The archive's files the wall names (MPCDI: warps, alpha and beta maps); empty otherwise.
  std::vector<ExtractedFile> files;
};

// Reads `text` (the file's contents) in `format`, or in the format its content shows when none
// is given. `path` names the file in every message. Throws LayoutError, one line naming the file
// and the JSON path of the field: "config.json: surfaces[0].screenCountX: expected a positive
// integer, got \"two\"" (also malformed JSON, with its line and column, and more than 64
// displays).
ImportedWall import_wall(std::string_view text, const std::filesystem::path& path,
                         std::optional<ImportFormat> format = std::nullopt);

// How an MPCDI calibration's files land beside the wall file.
struct MpcdiImport {
  // The folder, relative to the wall file, the maps are written to ("wall.calibration").
  std::string maps_folder;
  // The gamma of the projectors: an alpha map with gamma G embedded gets alpha_gamma =
  // display_gamma / G (docs/wall-import.md, "MPCDI").
  double display_gamma = 2.2;
};

// Reads mpcdi.xml (`xml`) of the MPCDI archive `path`, which holds the files `entries`: the 2D
// media profile, versions 1.0 and 2.0; every region a display, its warp, alpha and beta maps
// listed in ImportedWall::files. Throws LayoutError, one line naming the file, mpcdi.xml's line
// and the field ("cal.mpcdi: mpcdi.xml:7: display.buffer[0].region[1].xResolution: expected a
// whole number 1..4095, got \"0\""), also for another profile, malformed XML and a file the
// XML names that the archive lacks.
ImportedWall import_mpcdi(std::string_view xml, const std::vector<std::string>& entries,
                          const std::filesystem::path& path, const MpcdiImport& options);

// The mpirun hostfile of `l2wall run --mpi` for a wall of `display_count` displays whose
// pipeservers run on `hosts` (each host's together, as ImportedWall::hosts has them): one
// "HOST slots=N" line per host, rank 0 (the coordinator) on the first host, then the
// pipeservers in order, then one rank per board column (8 displays each) on the last host,
// after comment lines saying so and the -np it is for (docs/mpi-design.md). Empty without hosts.
std::string mpi_hostfile(const std::vector<std::string>& hosts, int display_count);

}  // namespace l2
