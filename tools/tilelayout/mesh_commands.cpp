#include "mesh_commands.hpp"

#include <fmt/format.h>

#include <iostream>

#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/mesh.hpp"
#include "network_needs.hpp"
#include "plan_outputs.hpp"
#include "tilelayout/pictures.hpp"
#include "tilelayout/plan_report.hpp"
#include "tilelayout/several_meshes.hpp"
#include "tilelayout/survival.hpp"
#include "verify/verify_run.hpp"
#include "verify_plan.hpp"

namespace l2 {
namespace {

std::string heading(const MeshPlan& m) {
  const Wall& w = m.layout.wall;
  const Mesh mesh = Mesh::fit(w.pipeserver_count, static_cast<int>(w.displays.size()),
                              {w.board_max_width, w.board_max_height});
  return mesh_heading(m.part, mesh.rows(), mesh.columns());
}

void print_plans(const Wall& wall, const std::vector<MeshPlan>& plans) {
  std::cout << fmt::format(
      "wall \"{}\" ({}): canvas {}x{}, {} displays in {} meshes (a strip header addresses {} "
      "displays), {} pipeservers; each mesh's plan below is in its own numbers: display ids as "
      "its headers carry them, pipeservers as its inputs\n",
      wall.name, wall.source.string(), wall.canvas_width, wall.canvas_height, wall.displays.size(),
      wall.mesh_count, kMaxDisplays, wall.pipeserver_count);
  for (const MeshPlan& m : plans) {
    std::cout << "\n"
              << heading(m) << "\n"
              << format_plan(m.layout) << format_network_needs(m.layout)
              << survival_line(m.layout.wall, survival(m.layout.wall)) << "\n";
  }
}

std::filesystem::path mesh_folder(const std::string& dir, int mesh) {
  return std::filesystem::path(dir) / fmt::format("mesh-{}", mesh);
}

// Plans, scans out and checks one mesh at a time, each freed before the next.
int verify_meshes(const Wall& wall, const std::vector<MeshPart>& parts, const PlanOutputs& o) {
  std::vector<int> wrong;
  for (const MeshPart& part : parts) {
    const MeshPlan m = plan_mesh(wall, part);
    std::cout << fmt::format("verifying mesh {} ({} of {}): {} displays, {} pipeservers\n",
                             part.mesh, part.mesh + 1, parts.size(), part.displays.size(),
                             part.pipeserver_count);
    std::cout.flush();
    if (verify_plan(m.layout, mesh_folder(o.verify_dir, part.mesh), o.parity,
                    fmt::format("mesh {}: ", part.mesh)) != 0) {
      wrong.push_back(part.mesh);
    }
  }
  if (wrong.empty()) {
    std::cout << fmt::format("every mesh right: {} displays in {} meshes\n", wall.displays.size(),
                             parts.size());
    return 0;
  }
  std::cout << fmt::format("routing wrong on mesh{} {} of {}\n", wrong.size() == 1 ? "" : "es",
                           number_runs(wrong), parts.size());
  return kExitRoutingWrong;
}

}  // namespace

int run_several_meshes(const Wall& wall, const PlanOutputs& o) {
  const std::vector<MeshPart> parts = mesh_parts(wall);
  std::vector<MeshPlan> plans;
  try {
    for (const MeshPart& part : parts) plans.push_back(plan_mesh(wall, part));
  } catch (const LayoutError& e) {
    std::cerr << "tilelayout: " << e.what() << "\n";
    return 1;
  }
  print_plans(wall, plans);
  try {
    if (!o.png_dir.empty()) {
      make_folders(o.png_dir, "--png");
      const auto path = std::filesystem::path(o.png_dir) / "meshes.png";
      write_png(path, meshes_page(wall));
      std::cout << "wrote " << path.string() << "\n";
      for (const MeshPlan& m : plans) write_pictures(m.layout, mesh_folder(o.png_dir, m.part.mesh));
    }
    if (!o.scanout_dir.empty()) {
      for (const MeshPlan& m : plans) {
        write_scanout(m.layout, mesh_folder(o.scanout_dir, m.part.mesh), o.parity, o.place);
      }
    }
    plans.clear();  // --verify plans each mesh again as it goes, so one is held at a time
    if (!o.verify_dir.empty()) return verify_meshes(wall, parts, o);
  } catch (const std::exception& e) {
    std::cerr << "tilelayout: " << e.what() << "\n";
    return 3;
  }
  return 0;
}

}  // namespace l2
