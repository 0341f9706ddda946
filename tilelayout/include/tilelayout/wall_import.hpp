// Importing a wall described in another system's configuration: Tide's JSON configuration,
// SAGE2's wall configuration and Unreal Engine nDisplay's .ndisplay file, each turned into the
// equivalent wall file (docs/wall-import.md says what maps to what). Pure: text in, text out; the
// tilelayout program reads and writes the files.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

enum class ImportFormat { Tide, Sage2, NDisplay };

// "tide", "sage2", "ndisplay": the names --format takes.
inline constexpr std::string_view kImportFormatNames[] = {"tide", "sage2", "ndisplay"};

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
};

// Reads `text` (the file's contents) in `format`, or in the format its content shows when none
// is given. `path` names the file in every message. Throws LayoutError, one line naming the file
// and the JSON path of the field: "config.json: surfaces[0].screenCountX: expected a positive
// integer, got \"two\"" (also malformed JSON, with its line and column, and more than 64
// displays).
ImportedWall import_wall(std::string_view text, const std::filesystem::path& path,
                         std::optional<ImportFormat> format = std::nullopt);

// The mpirun hostfile of `l2wall run --mpi` for a wall of `display_count` displays whose
// pipeservers run on `hosts` (each host's together, as ImportedWall::hosts has them): one
// "HOST slots=N" line per host, rank 0 (the coordinator) on the first host, then the
// pipeservers in order, then one rank per board column (8 displays each) on the last host,
// after comment lines saying so and the -np it is for (docs/mpi-design.md). Empty without hosts.
std::string mpi_hostfile(const std::vector<std::string>& hosts, int display_count);

}  // namespace l2
