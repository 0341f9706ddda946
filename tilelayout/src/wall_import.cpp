// import_wall: the file's JSON parsed, its format told from its content (or given), handed to
// that format's importer, and the draft written as a wall file; and the mpirun hostfile.
#include "tilelayout/wall_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "import_formats.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// Far more than any wall's configuration; a bound on what one import reads.
constexpr std::size_t kMaxFileBytes = 16 << 20;
// The first bytes of a zip file's first entry: an MPCDI archive.
constexpr std::string_view kZipMagic = "PK\x03\x04";

std::optional<ImportFormat> detect(const Json& doc) {
  if (doc.contains("nDisplay")) return ImportFormat::NDisplay;
  if (doc.contains("surfaces") || doc.contains("processes")) return ImportFormat::Tide;
  if (doc.contains("layout") || doc.contains("resolution")) return ImportFormat::Sage2;
  return std::nullopt;
}

}  // namespace

ImportedWall import_wall(std::string_view text, const std::filesystem::path& path,
                         std::optional<ImportFormat> format) {
  const std::string file = path.string();
  if (format == ImportFormat::Mpcdi || text.starts_with(kZipMagic)) {
    throw LayoutError(fmt::format(
        "{}: an MPCDI archive (a zip file): its mpcdi.xml is read by import_mpcdi", file));
  }
  if (text.size() > kMaxFileBytes) {
    throw LayoutError(fmt::format("{}: {} bytes, more than the {} a wall configuration may have",
                                  file, text.size(), kMaxFileBytes));
  }
  const Json doc = parse_json(text, file);
  if (!doc.is_object()) {
    throw LayoutError(fmt::format("{}: expected a JSON object at the top, got {}", file,
                                  doc.is_array() ? "an array" : doc.type_name()));
  }
  if (!format) format = detect(doc);
  if (!format) {
    throw LayoutError(fmt::format(
        "{}: not a configuration tilelayout import knows: no \"surfaces\" (Tide), \"layout\" "
        "(SAGE2) or \"nDisplay\" at the top; --format names the format",
        file));
  }
  const JsonAt root(&doc, "", file);
  const std::string stem = path.stem().string();
  WallDraft draft;
  switch (*format) {
    case ImportFormat::Tide:
      draft = import_tide(root, stem);
      break;
    case ImportFormat::Sage2:
      draft = import_sage2(root, stem);
      break;
    case ImportFormat::NDisplay:
      draft = import_ndisplay(root, stem);
      break;
    case ImportFormat::Mpcdi:
      break;  // refused above
  }
  ImportedWall out;
  out.format = *format;
  out.notes = draft.notes;
  out.display_count = static_cast<int>(draft.displays.size());
  out.toml = emit_wall(draft, file, out.hosts);
  return out;
}

std::string mpi_hostfile(const std::vector<std::string>& hosts, int display_count) {
  if (hosts.empty()) return "";
  std::vector<std::pair<std::string, int>> slots;
  for (const std::string& h : hosts) {
    if (slots.empty() || slots.back().first != h) {
      slots.emplace_back(h, 1);
    } else {
      ++slots.back().second;
    }
  }
  // A board column drives 8 displays (spec §5); l2wall runs one rank per column.
  const int columns = (display_count + 7) / 8;
  ++slots.front().second;
  slots.back().second += columns;
  std::string out = fmt::format(
      "# l2wall run --mpi: mpirun -np {} --hostfile THIS --map-by slot (docs/mpi-design.md).\n"
      "# Rank 0 (the coordinator) on the first host, the {} pipeservers on the hosts the "
      "configuration names, the {} board column rank(s) on the last host.\n",
      1 + hosts.size() + columns, hosts.size(), columns);
  for (const auto& [host, n] : slots) out += fmt::format("{} slots={}\n", host, n);
  return out;
}

}  // namespace l2
