// The displays of one golden entry's frame, produced in this process from scanned-out frames:
// through the emulated Lightning-2 (the DVI path) and through a compositing server on loopback
// TCP (the viz path), plus what every display should show.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct EntryDisplays {
  std::vector<int> ids;             // the wall's display ids, in wall order
  std::vector<RgbImage> emulator;   // DVI path: what the emulator's displays show after the swap
  std::vector<RgbImage> vizserver;  // vizserver path, same order; empty when it did not run
  std::vector<RgbImage> reference;  // what each display should show; empty when unknown
  std::string reference_name;       // "test pattern", "reference render"
  StripErrorCounts input_errors;    // spec §3 decode errors on the DVI inputs
};

// One scanned-out frame per pipeserver, in pipeserver order, through the emulated mesh of the
// wall (spec §5, §6): ticked once with the frames and once more, so the displays show them
// exactly as a live run's displays would one refresh later. Throws MeshError for a frame the
// mesh refuses (too large), naming it by `names[i]` when given.
std::vector<RgbImage> emulate_displays(const TileLayout& layout,
                                       const std::vector<RgbImage>& frames,
                                       StripErrorCounts& errors,
                                       const std::vector<std::string>& names = {});

// The packed tiles of every pipeserver's frame sent over loopback TCP to a compositing server,
// as `pipeserver --live --viz` sends them; returns its composed displays of `frame`.
std::vector<RgbImage> compose_on_vizserver(const TileLayout& layout,
                                           const std::vector<RgbImage>& frames, int frame);

// Every display pixel a tile covers showing test_pattern(display, x, y), (x, y) its canvas
// position; the rest black.
std::vector<RgbImage> test_pattern_displays(const TileLayout& layout);

// Routing-only entries: the test-pattern frames of `tilelayout --scanout --canvas-pattern` (no
// rendering) through the emulator and, if asked, the compositing server; the reference is the
// pattern. The pattern encodes canvas positions, so a change of the wall's geometry (a
// mullion, a display's position) changes the images, not only a change of routing.
EntryDisplays produce_test_pattern(const TileLayout& layout, int frame, bool vizserver);

// Frames a user captured, from `dir`: scanout-<i>.png for every pipeserver i (the names
// `tilelayout --scanout` writes), through the emulator only. Throws std::runtime_error naming
// a missing or unreadable file, MeshError for a frame the mesh refuses.
EntryDisplays produce_from_captured(const TileLayout& layout, const std::filesystem::path& dir);

}  // namespace l2
