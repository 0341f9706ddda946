// tilelayout: reads a wall file, prints the routing plan, and optionally writes pictures of it
// and the test-pattern frames every pipeserver would scan out.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "import_command.hpp"
#include "mesh_commands.hpp"
#include "network_needs.hpp"
#include "plan_outputs.hpp"
#include "tilelayout/fit.hpp"
#include "tilelayout/plan_report.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/survival.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/wall_file.hpp"
#include "verify_plan.hpp"

namespace {

int print_suggestions(const std::string& wall_path) {
  try {
    const l2::Wall wall = wall_path.empty() ? l2::default_wall() : l2::load_wall(wall_path);
    const l2::FitSuggestions fit = l2::suggest_fit(wall);
    for (const std::string& line : l2::suggestion_lines(wall, fit)) std::cout << line << "\n";
    for (const std::string& line : l2::survival_suggestions(wall, l2::survival(wall)))
      std::cout << line << "\n";
    const bool any = fit.fits || fit.height_at_width || fit.width_at_height ||
                     !fit.policies.empty() || fit.pipeserver_count;
    return any ? 0 : 1;
  } catch (const l2::LayoutError& e) {
    std::cerr << "tilelayout: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Plans how a display wall is tiled, which pipeserver renders each tile and where each "
      "tile sits in its framebuffer (spec §4), and prints the plan, ending with how many lost "
      "pipeservers the wall survives (l2wall run --survive-host-loss: their tiles go to the "
      "others' framebuffers) and the framebuffer_height the next one needs.\n"
      "Without --wall it uses the built-in default wall (walls/kd-2x2.toml).\n"
      "A wall of more than 64 displays is served by several meshes (a strip header addresses "
      "64): each mesh is planned and printed under a line naming its displays and pipeservers, "
      "and --png, --scanout and --verify write each mesh's files into DIR/mesh-<m>/ in the "
      "mesh's own numbers (--png also DIR/meshes.png: which mesh drives which display); "
      "--verify checks one mesh at a time, each report line after \"mesh <m>: \".\n"
      "Exit status: 0 plan printed, 1 invalid wall (one-line error on stderr), 2 usage error, "
      "3 output files could not be written, 4 --verify found pixels out of place.\n"
      "tilelayout import FILE writes the wall file of a wall described for Tide, SAGE2, "
      "nDisplay or in an MPCDI calibration (tilelayout import --help)."};
  std::string wall_path;
  std::string png_dir, scanout_dir, verify_dir;
  int parity = 0;
  bool print_default = false, suggest = false, canvas_pattern = false;
  CLI::Option* const wall_option =
      l2::add_wall_option(app, wall_path, "default: the built-in default wall (walls/kd-2x2.toml)");
  CLI::Option* const png_option =
      app.add_option("--png", png_dir,
                     "write pictures to DIR, each with a legend: pipeserver-N.png (framebuffer: "
                     "header gaps white, tiles coloured by display, labelled D<display> "
                     "L<logical tile>; a DEPTH tile's depth pixels darker) and wall.png (tiles "
                     "coloured by pipeserver, labelled P<pipeserver> L<logical tile>; a depth "
                     "wall's layers also as wall-layer-N.png, wall.png being layer 0)")
          ->type_name("DIR");
  CLI::Option* const scanout_option =
      app.add_option("--scanout", scanout_dir,
                     "write scanout-N.png to DIR: the 24-bit frame each pipeserver would scan out, "
                     "every header drawn, every tile filled with the routing test pattern")
          ->type_name("DIR");
  CLI::Option* const verify_option =
      app.add_option("--verify", verify_dir,
                     "scan out, route and check in one step: every pipeserver's --scanout frame "
                     "routed through the emulated mesh (DIR/scanout-N.png, DIR/display-D.png) and "
                     "every display pixel checked against the plan as lightning2_emu route "
                     "--verify does (DIR/verify-D.png, the report on stdout); exit 4 when any "
                     "pixel is wrong")
          ->type_name("DIR");
  // Options that would be ignored are usage errors: a --parity without --scanout or --verify,
  // or a wall or picture folder with --print-default.
  app.add_option("--parity", parity, "frame parity for --scanout and --verify headers")
      ->check(CLI::Range(0, 1));
  app.add_flag("--canvas-pattern", canvas_pattern,
               "--scanout tiles encode each pixel's canvas position, not its display position: "
               "the frames of the routing-only golden images (l2wall golden check --inputs)")
      ->needs(scanout_option);
  app.add_flag("--suggest", suggest,
               "print values that make the wall fit, each changed alone: the smallest "
               "framebuffer_height at its framebuffer_width and framebuffer_width at its height "
               "(header gaps included), the other assignment policies that fit and the fewest "
               "pipeservers that fit at its framebuffer size; then the framebuffer_height (at its "
               "framebuffer_width) with which it survives the loss of 1 pipeserver, and of 2 "
               "when it has 3 or more; exit 0, 1 when none fits")
      ->excludes(png_option)
      ->excludes(scanout_option)
      ->excludes(verify_option);
  app.add_flag("--print-default", print_default, "print the built-in default wall file, exit")
      ->excludes(wall_option)
      ->excludes(png_option)
      ->excludes(scanout_option)
      ->excludes(verify_option)
      ->excludes("--suggest");
  l2::ImportOptions import_options;
  std::string import_format;
  CLI::App* const import_command = app.add_subcommand(
      "import",
      "Print the wall file of a wall already described in another system's configuration: "
      "Tide's JSON configuration (surfaces, processes), SAGE2's wall configuration (layout, "
      "resolution, dimensions, displays), an Unreal Engine nDisplay .ndisplay file (version "
      "5: nodes, windows, viewports) or a VESA MPCDI calibration (.mpcdi: a zip of mpcdi.xml "
      "and its maps; the 2D media profile, versions 1.0 and 2.0). The displays land where the "
      "file puts them, with rotation and flip; one pipeserver per process or node the file "
      "names (else per display), the framebuffers the smallest that hold the tiles. Comments in "
      "it say where each value came from and what the wall file cannot carry (projection "
      "policies, cameras, stereo, warp meshes), which are also printed as notes: on stderr, or "
      "on stdout with --write. An MPCDI region becomes a display at its place in its buffer, "
      "its geometry warp, alpha map and beta map extracted with --write into a folder beside "
      "the wall file named after it (wall.toml: wall.calibration/) and named by warp, alpha, "
      "alpha_gamma and beta; without --write the wall is printed and nothing extracted. What "
      "maps to what: docs/wall-import.md.\n"
      "Exit status: 0 written, 1 the file cannot be imported (one line naming the file and the "
      "field, e.g. config.json: surfaces[0].screenCountX: expected a positive integer, got "
      "\"two\"; cal.mpcdi: mpcdi.xml:2: MPCDI.profile: \"3d\" is the 3D media profile: ...), "
      "2 usage error, 3 an output file could not be written.");
  import_command
      ->add_option("FILE", import_options.file, "the configuration (JSON) or MPCDI calibration")
      ->required()
      ->check(CLI::ExistingFile);
  import_command
      ->add_option("--format", import_format,
                   "the file's format: tide, sage2, ndisplay or mpcdi (default: told from its "
                   "content: a zip file is MPCDI; in JSON \"nDisplay\" at the top is nDisplay, "
                   "\"surfaces\" or \"processes\" Tide, \"layout\" or \"resolution\" SAGE2)")
      ->check(CLI::IsMember({"tide", "sage2", "ndisplay", "mpcdi"}));
  import_command
      ->add_option("--write", import_options.out,
                   "write the wall file to FILE instead of printing it (then tilelayout --wall "
                   "FILE and l2wall run --wall FILE take it); an MPCDI calibration's maps go "
                   "into STEM.calibration/ beside it (FILE's name without its extension), and "
                   "the wall is read back with them before it is written")
      ->type_name("FILE");
  import_command
      ->add_option("--display-gamma", import_options.display_gamma,
                   "MPCDI only: the projectors' gamma, 1..4 (default 2.2): an alpha map with "
                   "gamma G embedded (its gammaEmbedded) gets alpha_gamma = this / G, so that "
                   "its weights land as light")
      ->check(CLI::Range(1.0, 4.0))
      ->type_name("G");
  import_command
      ->add_option(
          "--hostfile", import_options.hostfile,
          "also write the mpirun hostfile of l2wall run --mpi to OUT: one \"HOST slots=N\" line "
          "per host the file names, rank 0 (the coordinator) on the first, the "
          "pipeservers in the wall file's order, one rank per board column (8 displays) "
          "on the last; its first lines give the mpirun -np it is for "
          "(docs/mpi-design.md). Exit 1 when the file names no host (SAGE2 configurations "
          "as published name none)")
      ->type_name("OUT");
  app.callback([&] {
    if (app.count("--parity") > 0 && scanout_dir.empty() && verify_dir.empty()) {
      throw CLI::ValidationError("--parity requires --scanout or --verify");
    }
    if (import_command->parsed()) {
      for (const char* option : {"--wall", "--png", "--scanout", "--verify", "--parity",
                                 "--canvas-pattern", "--suggest", "--print-default"}) {
        if (app.count(option) > 0)
          throw CLI::ValidationError(fmt::format("import does not take {}", option));
      }
    }
  });
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;

  if (import_command->parsed()) {
    if (!import_format.empty()) {
      const auto* const name = std::find(std::begin(l2::kImportFormatNames),
                                         std::end(l2::kImportFormatNames), import_format);
      import_options.format =
          static_cast<l2::ImportFormat>(name - std::begin(l2::kImportFormatNames));
    }
    return l2::run_import(import_options);
  }
  if (print_default) {
    std::cout << l2::default_wall_toml();
    return 0;
  }
  if (suggest) return print_suggestions(wall_path);
  l2::TileLayout layout;
  try {
    const l2::Wall wall = wall_path.empty() ? l2::default_wall() : l2::load_wall(wall_path);
    if (wall.mesh_count > 1) {
      return l2::run_several_meshes(
          wall, {png_dir, scanout_dir, verify_dir, parity == 1,
                 canvas_pattern ? l2::PatternPlace::Canvas : l2::PatternPlace::Display});
    }
    layout = l2::plan_layout(wall);
  } catch (const l2::LayoutError& e) {
    std::cerr << "tilelayout: " << e.what() << "\n";
    return 1;
  }
  std::cout << l2::format_plan(layout) << l2::format_network_needs(layout)
            << l2::survival_line(layout.wall, l2::survival(layout.wall)) << "\n";
  try {
    if (!png_dir.empty()) write_pictures(layout, png_dir);
    if (!scanout_dir.empty())
      write_scanout(layout, scanout_dir, parity == 1,
                    canvas_pattern ? l2::PatternPlace::Canvas : l2::PatternPlace::Display);
    if (!verify_dir.empty()) return l2::verify_plan(layout, verify_dir, parity == 1);
  } catch (const std::exception& e) {
    std::cerr << "tilelayout: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
