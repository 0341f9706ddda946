#include "l2wall/run_pictures.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "display_compare.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "l2wall/run_fault.hpp"
#include "wall_picture.hpp"

namespace l2 {

std::vector<int> write_display_pictures(const std::filesystem::path& dir, const Wall& wall,
                                        const DisplayPictures& display, const std::string& suffix) {
  make_folders(dir);
  std::vector<int> missing;
  for (const Display& d : wall.displays) {
    const RgbImage& picture = display(d.id);
    if (picture.empty()) {
      missing.push_back(d.id);
      continue;
    }
    write_png(dir / fmt::format("display-{}{}.png", d.id, suffix), picture);
  }
  if (missing.empty())
    write_png(dir / fmt::format("wall{}.png", suffix), compose_wall_picture(wall, display));
  return missing;
}

int compare_paths(int frame, const Wall& wall, const DisplayPictures& via_dvi,
                  const DisplayPictures& via_viz, bool tamper_display_0,
                  const std::filesystem::path& out) {
  int compared = 0;
  for (const Display& d : wall.displays) {
    const RgbImage& dvi = via_dvi(d.id);
    RgbImage tampered;
    const RgbImage* viz = &via_viz(d.id);
    if (tamper_display_0 && d.id == 0) {
      // Fault injection: one pixel off, to show what a mismatch looks like.
      tampered = *viz;
      const Rgb p = tampered.at(tampered.width() / 2, tampered.height() / 2);
      tampered.set(tampered.width() / 2, tampered.height() / 2,
                   Rgb{static_cast<std::uint8_t>(p.r ^ 0x80), p.g, p.b});
      viz = &tampered;
    }
    const DisplayDiff diff = compare_displays(dvi, *viz);
    ++compared;
    if (diff.identical()) continue;
    const auto dir = out / fmt::format("mismatch-frame-{}", frame);
    make_folders(dir);
    write_png(dir / fmt::format("display-{}-dvi.png", d.id), dvi);
    write_png(dir / fmt::format("display-{}-vizserver.png", d.id), *viz);
    write_png(dir / fmt::format("display-{}-diff.png", d.id), diff.picture);
    throw RunFault(fmt::format(
        "frame {}: display {} differs between the DVI and vizserver paths in {} pixels; "
        "both pictures and the difference are in {}",
        frame, d.id, diff.differing_pixels, dir.string()));
  }
  return compared;
}

std::string pictures_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    if (entry.is_regular_file(error)) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return fmt::format("{}", fmt::join(names, ", "));
}

void remove_earlier_pictures(const std::filesystem::path& out) {
  remove_earlier(
      out,
      [](const std::filesystem::directory_entry& entry) {
        const std::string name = entry.path().filename().string();
        return entry.is_directory() && (name == "fault" || numbered_name(name, "frame-") ||
                                        numbered_name(name, "mismatch-frame-"));
      },
      "the pictures of an earlier run");
}

}  // namespace l2
