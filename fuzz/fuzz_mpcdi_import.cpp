// tilelayout import of an MPCDI calibration's mpcdi.xml (import_mpcdi; docs/wall-import.md,
// "MPCDI") on arbitrary bytes, the archive holding a fixed list of files. Out comes a wall file
// that parse_wall reads (once the map keys, naming files not written here, are left out), with
// every file to extract one the archive holds and its new name inside the maps folder (no
// archive name can put a file elsewhere), or one LayoutError line naming the file; nothing else.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "tilelayout/wall_import.hpp"

using l2::fuzz::require;

namespace {

const std::vector<std::string> kEntries = {
    "mpcdi.xml",       "left/warp.pfm",  "left/alpha.png", "right/warp.pfm",
    "right/alpha.png", "right/beta.png", "a.png",          "w.pfm"};

// The wall without the keys that name the extracted files.
std::string without_map_keys(const std::string& toml) {
  std::istringstream in(toml);
  std::string out, line;
  while (std::getline(in, line)) {
    bool map_key = false;
    for (const std::string_view key : {"warp = ", "alpha = ", "alpha_gamma = ", "beta = "})
      map_key = map_key || line.rfind(key, 0) == 0;
    if (!map_key) out += line + "\n";
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view xml(reinterpret_cast<const char*>(data), size);
  try {
    const l2::ImportedWall imported =
        l2::import_mpcdi(xml, kEntries, "fuzz.mpcdi", {"wall.calibration", 2.2});
    for (const std::string& note : imported.notes)
      l2::fuzz::require_one_line(note, "an import note is one line");
    for (const l2::ExtractedFile& f : imported.files) {
      require(std::find(kEntries.begin(), kEntries.end(), f.entry) != kEntries.end(),
              "every file to extract is one the archive holds");
      const std::string_view name = std::string_view(f.path).substr(17);
      require(f.path.rfind("wall.calibration/", 0) == 0 && name.find('/') == std::string::npos &&
                  name.find("..") == std::string::npos && !name.empty(),
              "every extracted file lands in the maps folder");
    }
    const l2::Wall wall = l2::parse_wall(without_map_keys(imported.toml), "fuzz.toml");
    require(!wall.displays.empty() && wall.displays.size() <= 64 &&
                static_cast<int>(wall.displays.size()) == imported.display_count,
            "an imported wall has its 1..64 regions as displays");
  } catch (const l2::LayoutError& e) {
    const std::string_view message = e.what();
    l2::fuzz::require_one_line(message, "an import error is one line");
    require(message.rfind("fuzz.mpcdi: ", 0) == 0, "an import error names the file first");
  }
  return 0;
}
