#include "verify_plan.hpp"

#include <fmt/format.h>

#include <iostream>
#include <sstream>
#include <string>

#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "tilelayout/test_frame.hpp"
#include "verify/verify_run.hpp"

namespace l2 {

int verify_plan(const TileLayout& layout, const std::filesystem::path& dir, bool parity,
                std::string_view prefix) {
  make_folders(dir, "--verify");
  std::vector<RgbImage> frames;
  for (const PipeserverPlan& s : layout.pipeservers) {
    frames.push_back(test_frame(s, parity));
    write_png(dir / fmt::format("scanout-{}.png", s.pipeserver), frames.back());
  }
  const std::vector<RgbImage> shown = route_on_wall(layout.wall, frames);
  std::vector<const RgbImage*> routed;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    write_png(dir / fmt::format("display-{}.png", layout.wall.displays[i].id), shown[i]);
    routed.push_back(&shown[i]);
  }
  std::ostringstream report;
  report << fmt::format("wrote {}/scanout-<n>.png and display-<d>.png: scanned out, routed\n",
                        dir.string());
  const bool right = verify_and_report(layout, frames, routed, dir, report);
  std::istringstream lines(report.str());
  for (std::string line; std::getline(lines, line);) std::cout << prefix << line << "\n";
  return right ? 0 : kExitRoutingWrong;
}

}  // namespace l2
