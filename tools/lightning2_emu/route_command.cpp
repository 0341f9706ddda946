// `lightning2_emu route`: one captured frame per input through the mesh, every strip routed
// (no frame sequencing: one frame has nothing to wait for).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/frame_files.hpp"
#include "lightning2_emu/out_folder.hpp"
#include "lightning2_emu/report_json.hpp"
#include "lightning2_emu/router.hpp"

namespace l2 {

int run_route(const CommonOptions& o) {
  const Setup setup = make_setup(o);
  const Mesh& mesh = setup.config.mesh;
  prepare_out(o.out);
  std::vector<RgbImage> images;
  std::vector<InputFrame> frames;
  images.reserve(o.inputs.size());
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    // Checked on the file's header: a picture larger than a board takes is never allocated.
    images.push_back(read_scanned_frame(o.inputs[i], [&](int width, int height) {
      mesh.check_input(static_cast<int>(i), width, height, o.inputs[i]);
    }));
  }
  for (const RgbImage& image : images) frames.push_back(InputFrame::of(image));

  WorkerPool pool(setup.config.workers);
  Router router(mesh, setup.config.displays, pool, setup.config.background);
  const RouteReport report = router.route(frames);

  // One file after the other, report.json last. When one cannot be written the error says what
  // OUT holds of this run: a file not named there is missing or an earlier run's.
  std::vector<std::string> written;
  try {
    std::vector<const RgbImage*> by_id(kMaxDisplays, nullptr);
    for (int d = 0; d < router.display_count(); ++d) {
      const DisplayBuffers& display = router.display(d);
      by_id[display.id()] = &display.back();
      const std::string name = fmt::format("display-{}.png", display.id());
      write_png(o.out / name, display.back());
      written.push_back(name);
    }
    if (setup.from_wall) {
      write_png(o.out / "wall.png", compose_wall(setup, by_id));
      written.push_back("wall.png");
    }
    write_route_report(o.out / "report.json", report, mesh, o.inputs);
  } catch (const std::runtime_error& e) {
    throw partly_written(e, o.out, fmt::format("{}", fmt::join(written, ", ")), "no report.json");
  }

  const StripErrorCounts errors = report.errors();
  fmt::print("routed {} inputs to {} displays ({}); {} strip errors; wrote {}\n", frames.size(),
             router.display_count(), mesh.describe(), errors.total(), o.out.string());
  return o.verify ? verify_route(o, images, router) : 0;
}

}  // namespace l2
