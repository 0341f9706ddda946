#include "verify/verify_run.hpp"

#include <fmt/format.h>

#include "image/png_io.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/wall_emulator.hpp"
#include "verify/check_picture.hpp"
#include "verify/check_report.hpp"

namespace l2 {

std::vector<RgbImage> route_on_wall(const Wall& wall, std::span<const RgbImage> frames,
                                    int workers) {
  std::vector<DisplaySpec> specs = display_specs(wall);
  const InputLimit limit{wall.board_max_width, wall.board_max_height};
  const Mesh mesh = Mesh::fit(std::max(wall.pipeserver_count, static_cast<int>(frames.size())),
                              static_cast<int>(specs.size()), limit);
  std::vector<InputFrame> views;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    mesh.check_input(static_cast<int>(i), frames[i].width(), frames[i].height(),
                     fmt::format("input {}", i));
    views.push_back(InputFrame::of(frames[i]));
  }
  WorkerPool pool(workers);
  Router router(mesh, specs, pool);
  router.route(views);
  std::vector<RgbImage> shown;
  for (const Display& d : wall.displays) {
    shown.push_back(router.display(router.index_of_display(d.id)).back());
  }
  return shown;
}

bool verify_and_report(const TileLayout& layout, std::span<const RgbImage> frames,
                       std::span<const RgbImage* const> routed, const std::filesystem::path& dir,
                       std::ostream& out) {
  const RoutingCheck check = check_routing(layout, frames, routed);
  for (std::size_t i = 0; i < check.displays.size(); ++i) {
    const DisplayCheck& d = check.displays[i];
    // Without the router's picture, the check's colours on black still say everything.
    const RgbImage blank(d.width, d.height);
    const RgbImage& shown = i < routed.size() && routed[i] != nullptr ? *routed[i] : blank;
    write_png(dir / fmt::format("verify-{}.png", d.display), check_picture(check, i, shown));
  }
  for (const std::string& line : check_report(check)) out << line << "\n";
  out << fmt::format("wrote {}/verify-<d>.png: the displays, wrong pixels marked\n", dir.string());
  return check.clean();
}

}  // namespace l2
