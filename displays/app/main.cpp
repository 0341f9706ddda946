// show_wall: shows the output displays an emulator run wrote (DIR/display-<d>.png) on real
// screens, laid out as the wall file places them — the standalone face of the displays part.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "display_files.hpp"
#include "displays/wall_presenter.hpp"
#include "tilelayout/wall_file.hpp"

namespace {

struct Options {
  std::filesystem::path displays_from;
  std::filesystem::path wall_file;
  std::string show = "window";
  long frames = 0;
  std::filesystem::path screenshot_dir;
  double refresh_hz = 60.0;
  bool no_vsync = false;
};

l2::Wall load_wall_or_row(const Options& o, std::vector<l2::RgbImage>& images) {
  if (o.wall_file.empty()) {
    images = l2::read_display_files(o.displays_from);
    return l2::row_wall(images, 16);
  }
  l2::Wall wall = l2::load_wall(o.wall_file);
  images = l2::read_display_files(o.displays_from, wall);
  return wall;
}

void save(l2::WallPresenter& shown, const std::filesystem::path& dir, const std::string& prefix) {
  const auto files = l2::save_screenshots(shown, dir, prefix);
  fmt::print("show_wall: saved {} screenshot(s) in {}\n", files.size(), dir.string());
  std::fflush(stdout);
}

// The frame loop: presents at --refresh, reacts to keys, stops after --frames or on quit.
void run(const Options& o, l2::ShowMode mode) {
  std::vector<l2::RgbImage> images;
  const l2::Wall wall = load_wall_or_row(o, images);
  const auto shown = l2::open_presenter(mode, wall, {.vsync = !o.no_vsync, .title = "show_wall"});
  const std::filesystem::path shot_dir =
      o.screenshot_dir.empty() ? "screenshots" : o.screenshot_dir;
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / o.refresh_hz));
  l2::FpsMeter meter;
  l2::FrameInfo info;  // no pipeline behind the images: latency stays unknown
  auto next = std::chrono::steady_clock::now();
  for (bool quit = false; !quit;) {
    shown->present(info, images);
    meter.tick(std::chrono::steady_clock::now());
    if (!info.paused) ++info.frame;
    if (o.frames > 0 && info.frame >= o.frames) break;
    for (auto a = shown->poll_events(); a != l2::UserAction::None; a = shown->poll_events()) {
      if (a == l2::UserAction::Quit) quit = true;
      if (a == l2::UserAction::PauseToggled) info.paused = !info.paused;
      if (a == l2::UserAction::Screenshot)
        save(*shown, shot_dir, fmt::format("frame-{:06}-", info.frame));
    }
    info.fps = meter.fps();
    next += period;
    std::this_thread::sleep_until(next);
  }
  if (!o.screenshot_dir.empty()) save(*shown, o.screenshot_dir, "");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Shows the output displays of a Lightning-2 emulator run (DIR/display-<d>.png) on screen,\n"
      "laid out as the wall file places them.\n"
      "  --show window    one window with the whole wall, mullions as dark bars, scaled to fit\n"
      "                   the screen (pixel for pixel when it fits) and an overlay line.\n"
      "  --show monitors  each display fullscreen on the monitor named by its `monitor` field\n"
      "                   in the wall file (GLFW's monitor name, or its index); refused with\n"
      "                   the list of monitors when one is missing.\n"
      "Keys: space pauses, s saves a screenshot of every display (PNG), q or Esc quits.\n"
      "Without a screen, run under Xvfb: xvfb-run -a -s '-screen 0 2600x2200x24' show_wall ...",
      "show_wall"};
  Options o;
  app.add_option("--displays-from", o.displays_from,
                 "Folder with display-0.png, display-1.png, ... (as an emulator run writes them)")
      ->required()
      ->check(CLI::ExistingDirectory);
  l2::add_wall_option(app, o.wall_file, "places the displays; default: all displays in a row");
  app.add_option("--show", o.show, "window | monitors")
      ->check(CLI::IsMember({"window", "monitors"}))
      ->capture_default_str();
  app.add_option("--frames", o.frames, "Quit after N frames (0: run until q, Esc or close)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--screenshot", o.screenshot_dir,
                 "At the end, save what the screens show: DIR/display-<d>.png per display and\n"
                 "DIR/window-<i>.png per window; the s key saves here too (default ./screenshots)")
      ->type_name("DIR");
  l2::add_refresh_option(app, o.refresh_hz, false, "frames presented per second")
      ->capture_default_str();
  app.add_flag("--no-vsync", o.no_vsync, "Swap at once instead of on vertical blank");
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;

  try {
    run(o, *l2::parse_show_mode(o.show));
  } catch (const std::exception& e) {
    fmt::print(stderr, "show_wall: {}\n", e.what());
    return 1;
  }
  return 0;
}
