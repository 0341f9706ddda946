// Measures how far reassembled displays are from the reference render, for the tolerance
// documented in pipeserver/README.md: every example wall (or the given ones) x every scene at
// the scenes' default sizes, a few frames each.

#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "image/png_io.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace {

// The wall as a viewer sees it: every display reassembled from the pipeservers' frames, placed
// at its canvas position, mullions dark grey.
int write_picture(const std::filesystem::path& out, const std::filesystem::path& wall_file,
                  const std::string& scene_name, int frame) {
  const l2::TileLayout layout = l2::plan_layout(l2::load_wall(wall_file));
  auto scene = l2::make_scene(scene_name);
  const auto check = l2::test::check_wall(layout, *scene, frame);
  l2::RgbImage canvas(layout.wall.canvas_width, layout.wall.canvas_height, {40, 40, 40});
  for (const auto& d : layout.wall.displays) {
    const auto& img = check.reassembly.displays[static_cast<std::size_t>(d.id)];
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) canvas.set(d.canvas_x + x, d.canvas_y + y, img.at(x, y));
  }
  l2::write_png(out, canvas);
  std::printf("wrote %s: %s, scene %s, frame %d, %ld decode errors\n", out.c_str(),
              wall_file.filename().c_str(), scene_name.c_str(), frame,
              static_cast<long>(check.reassembly.errors.total()));
  return 0;
}

// Every wall file of one mesh in the repository's walls/ (those of several meshes are
// hundreds of full-size panels).
std::vector<std::filesystem::path> example_walls() {
  std::vector<std::filesystem::path> walls;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(L2_SOURCE_DIR) / "walls"))
    if (e.path().extension() == ".toml" && l2::load_wall(e.path()).mesh_count == 1)
      walls.push_back(e.path());
  return walls;
}

// One line per wall, scene and frame: how far the reassembled displays are from the reference.
void print_tolerance_table(const std::vector<std::filesystem::path>& walls) {
  std::printf("%-24s %-11s %5s %10s %9s %9s %9s %6s %4s %6s\n", "wall", "scene", "frame", "pixels",
              "differ", "%", ">1", ">1 %", "max", "@edge");
  for (const auto& path : walls) {
    const l2::TileLayout layout = l2::plan_layout(l2::load_wall(path));
    for (const auto& name : l2::built_in_scene_names()) {
      auto scene = l2::make_scene(name);
      for (int frame : {0, 17, 40}) {
        const auto check = l2::test::check_wall(layout, *scene, frame, true);
        l2::test::ImageDiff all;
        for (const auto& d : check.diffs) all += d;
        const double n = static_cast<double>(check.display_pixels);
        std::printf("%-24s %-11s %5d %10ld %9ld %9.4f %9ld %6.4f %4d %6ld%s\n",
                    path.filename().string().c_str(), name.c_str(), frame, check.display_pixels,
                    all.pixels_differing, 100.0 * static_cast<double>(all.pixels_differing) / n,
                    all.pixels_beyond_one, 100.0 * static_cast<double>(all.pixels_beyond_one) / n,
                    all.max_channel_diff, all.at_tile_edges,
                    check.reassembly.errors.total() ? "  DECODE ERRORS" : "");
        std::fflush(stdout);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "pipeserver_verify: how far reassembled displays are from the reference render. Renders\n"
      "every scene on every pipeserver of each wall (frames 0, 17 and 40), routes the strips back\n"
      "into displays and prints, per wall, scene and frame, the pixels that differ from a\n"
      "display-sized render, by more than one level, the largest difference, and how many lie on\n"
      "tile edges. With --picture, writes one reassembled wall as a PNG instead."};
  std::vector<std::filesystem::path> walls;
  std::filesystem::path picture;
  std::string scene_name = "mesh";
  int picture_frame = 0;
  l2::add_wall_option(app, walls, "repeat for several walls; default: every wall in walls/");
  app.add_option("--picture", picture,
                 "write the one --wall given, reassembled, to this PNG (mullions dark grey)");
  app.add_option("--scene", scene_name, "--picture: scene to render")
      ->check(CLI::IsMember(l2::built_in_scene_names()))
      ->capture_default_str();
  app.add_option("--frame", picture_frame, "--picture: frame to render")
      ->check(CLI::Range(0, 1 << 30))
      ->capture_default_str();
  app.callback([&] {
    if (!picture.empty() && walls.size() != 1) {
      throw CLI::ValidationError("--picture",
                                 fmt::format("takes exactly one wall file, got {}", walls.size()));
    }
  });
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    if (!picture.empty()) return write_picture(picture, walls.front(), scene_name, picture_frame);
    print_tolerance_table(walls.empty() ? example_walls() : walls);
  } catch (const std::exception& e) {  // a wall file that cannot be used, a picture not written
    std::fprintf(stderr, "pipeserver_verify: %s\n", e.what());
    return 1;
  }
  return 0;
}
