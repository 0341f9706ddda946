// What every importer makes of its file before it is a wall file: the displays where the file
// puts them, the hosts it names and what it could not carry; and the one writer that turns it
// into wall-file text whose pipeservers and framebuffers plan (import_emit.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/orientation.hpp"

namespace l2 {

// A wall holds at most this many displays: ids are 6 bits in the strip headers.
inline constexpr int kMaxImportedDisplays = 64;
// Display sizes are 12-bit header fields.
inline constexpr int kMaxImportedSide = 4095;

struct DraftDisplay {
  int width = 0, height = 0;  // native, as the panel reports it
  int x = 0, y = 0;           // top-left of its canvas rectangle, before the canvas is shifted
  Orientation orientation;
  std::string origin;  // where in the file it came from, for the comment beside it
  // Further lines of its [[display]] entry, as written ("warp = \"w.pfm\"  # ..."): the files
  // it names, which need not exist yet when the wall is planned.
  std::vector<std::string> keys;
};

// Displays that are a grid of identical ones, in id order (row by row).
struct DraftGrid {
  int columns = 1, rows = 1;
  int width = 0, height = 0;
  int mullion_x = 0, mullion_y = 0;
};

struct WallDraft {
  std::string name;
  std::vector<std::string> header;  // comment lines: which file, which format, what was read
  std::optional<DraftGrid> grid;
  std::vector<DraftDisplay> displays;
  std::vector<std::string> hosts;  // one per process or node, in file order; empty: none named
  std::vector<std::string> notes;
};

// The wall file of `draft`: [display_grid] or [[display]] entries (moved so the canvas starts at
// 0,0), a k-d tiling, and pipeservers that plan: one per host named (each host running more
// when the framebuffers cannot hold the wall otherwise), else one per display, framebuffers the
// smallest that hold the tiles (suggest_fit), the boards' limits raised to them when needed.
// `hosts_out` gets the host of every pipeserver. Throws LayoutError naming `file`.
std::string emit_wall(const WallDraft& draft, const std::string& file,
                      std::vector<std::string>& hosts_out);

// The refusal of a file with more displays than a wall holds: "FILE: WHERE: 72 displays, more
// than the 64 a wall can address (ids 0..63)".
[[noreturn]] void too_many_displays(const std::string& file, const std::string& where,
                                    long long count);

}  // namespace l2
