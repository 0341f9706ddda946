// lightning2_emu: the Lightning-2 emulator on captured frames.
#include <fmt/format.h>

#include <exception>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "commands.hpp"

namespace {

void add_common(CLI::App& cmd, l2::CommonOptions& o) {
  cmd.add_option("--displays", o.displays,
                 "Output displays 0, 1, ... as WxH[,WxH...] (mesh: as many board columns as "
                 "needed)");
  l2::add_wall_option(cmd, o.wall, "displays, swap groups and board limit from the wall");
  cmd.add_option("--groups", o.groups,
                 "Swap-lock group of each display, e.g. 0,0,1,1 (default: all in group 0)");
  cmd.add_option("--mesh", o.mesh,
                 "Mesh as ROWSxCOLUMNS boards (4 inputs a row, 8 displays a column); default: "
                 "the smallest that fits");
  cmd.add_option("--board-max", o.board_max, "Largest input a board accepts, WxH")
      ->capture_default_str();
  cmd.add_option("--background", o.background, "Colour of pixels no strip writes, RRGGBB")
      ->capture_default_str();
  l2::add_threads_option(cmd, o.threads);
  l2::add_out_option(cmd, o.out, "the displays, the report and the pictures")->required();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Lightning-2 emulator: reads strip headers (spec §2-§3) out of scanned-out input frames "
      "and routes their strips to output displays through a mesh of boards (spec §5-§6)."};
  app.require_subcommand(1);

  l2::CommonOptions route_options;
  CLI::App* route = app.add_subcommand(
      "route",
      "Route one frame per input (input i is the i-th file); writes OUT/display-<d>.png, "
      "OUT/report.json and, with --wall, OUT/wall.png");
  add_common(*route, route_options);
  route->add_option("inputs", route_options.inputs, "Input frames IN0.png IN1.png ...")->required();
  route
      ->add_flag("--verify", route_options.verify,
                 "Check every display pixel against the wall's plan through the routing test "
                 "pattern (tilelayout --scanout frames, or any frames whose tiles show it): "
                 "prints per display the pixels right, missing, misplaced, written twice and "
                 "behind mullions, and each misplaced run with its input, row, column, header "
                 "and where it belongs; writes OUT/verify-<d>.png. Exit 4 when anything is wrong")
      ->needs("--wall");

  l2::CommonOptions seq_options;
  int ticks = 0;
  CLI::App* sequence = app.add_subcommand(
      "sequence",
      "Run folders of frames over time (one folder per input, frames sorted by name, one per "
      "refresh) with the parity, torn, idle and latency rules of spec §6; writes "
      "OUT/display-<d>/frame-<t>.png for every refresh, OUT/report.json and, with --wall, "
      "OUT/wall/frame-<t>.png");
  add_common(*sequence, seq_options);
  sequence
      ->add_option("--ticks", ticks,
                   "Refreshes to run, 1..100000 (default: the longest input's frame count + "
                   "1; an input past its last frame keeps scanning it out)")
      ->check(CLI::Range(1, 100000));
  sequence->add_option("inputs", seq_options.inputs, "Input folders IN0/ IN1/ ...")->required();
  l2::ShowOptions show;
  sequence
      ->add_option("--show", show.mode,
                   "Play the sequence on screen, one refresh per 1/--refresh s (what the displays "
                   "show during each refresh: spec §6). window: one window laying out the wall "
                   "(--wall; --displays: in a row) and an overlay line with the refresh number, "
                   "fps and latency. "
                   "monitors: each display fullscreen on the monitor its wall-file `monitor` "
                   "names (--displays: display i on monitor i). Keys: space pauses, s saves "
                   "screenshots to OUT/screenshots/, q or Esc stop the sequence there. Needs an "
                   "X display (without one, run under Xvfb)")
      ->check(CLI::IsMember({"window", "monitors"}));
  l2::add_refresh_option(*sequence, show.refresh_hz, true,
                         "With --show: refreshes per second on screen (default: the wall's "
                         "refresh_hz, 60 with --displays); 0 = as fast as possible")
      ->needs("--show");
  sequence
      ->add_option("--show-readback", show.readback,
                   "Verification aid for --show: after every refresh, read the windows back "
                   "from the X server into DIR/frame-<t>/display-<d>.png and window-<i>.png")
      ->needs("--show");

  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    if (*route) return l2::run_route(route_options);
    return l2::run_sequence(seq_options, ticks, show);
  } catch (const std::invalid_argument& e) {
    // What the options say together or in their text (frame_files.cpp, setup.cpp): a usage
    // error, as the ones CLI11 finds. A wall file or frame that cannot be used is exit 1.
    fmt::print(stderr, "lightning2_emu: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "lightning2_emu: {}\n", e.what());
    return 1;
  }
}
