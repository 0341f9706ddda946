// The lightning2_emu subcommands: options shared by both, and their entry points.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "lightning2_emu/emulator.hpp"

namespace l2 {

struct CommonOptions {
  std::string displays;  // "WxH,WxH"
  std::string wall;      // wall file, instead of displays
  std::string groups;    // "0,0,1" swap group per display (--displays only)
  std::string mesh;      // "RxC" boards; empty: the smallest that fits
  std::string board_max = "1280x1024";
  std::string background = "000000";
  int threads = 1;  // --threads (command_line/options.hpp)
  std::filesystem::path out;
  std::vector<std::string> inputs;  // frame files (route) or folders (sequence)
  bool verify = false;              // route --verify: check the displays against the wall
};

// What both commands build from the options: the emulator's configuration and, for --wall,
// where each display sits on the wall.
struct Setup {
  EmulatorConfig config;
  bool from_wall = false;
  struct Placement {
    int display = 0, x = 0, y = 0;
  };
  std::vector<Placement> placements;  // --wall: canvas position of every display
  int canvas_width = 0, canvas_height = 0;
};
Setup make_setup(const CommonOptions& options);

// The displays as placed on the wall, mullions (canvas not on any display) in dark grey.
// shown_by_id[d] is what display d shows (nullptr: not configured).
RgbImage compose_wall(const Setup& setup, const std::vector<const RgbImage*>& shown_by_id);

// sequence --show (sequence_show.hpp): the displays on screen, refresh by refresh.
struct ShowOptions {
  std::string mode;                // window | monitors; empty: not shown
  double refresh_hz = -1;          // below 0: the wall's rate (60 without --wall); 0: no wait
  std::filesystem::path readback;  // verification aid: what the screen shows, per refresh
};

int run_route(const CommonOptions& options);
// route --verify (route_verify.cpp): checks what `router` routed from `frames` against the
// plan of options.wall, writes OUT/verify-<d>.png and prints the report; the exit status.
int verify_route(const CommonOptions& options, std::span<const RgbImage> frames,
                 const Router& router);
int run_sequence(const CommonOptions& options, int ticks, const ShowOptions& show = {});

}  // namespace l2
