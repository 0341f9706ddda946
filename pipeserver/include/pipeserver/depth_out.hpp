// A packed tile out of the window it was rendered in: its colour pixels, and for a DEPTH tile
// (spec §7) the 24-bit depth buffer under it as pixels D = R<<16 | G<<8 | B in the w columns
// after its colour, into the scanned-out frame.
#pragma once

#include <cstdint>
#include <span>

#include "pipeserver/gl_context.hpp"
#include "tilelayout/sparse_depth.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Depth of a cleared pixel: the far plane, which never wins a composite.
inline constexpr std::uint32_t kFarDepth = 0xFFFFFF;

// Where a tile was rendered: the top-left of its pixels in `window`, rows from the top.
struct TileInWindow {
  const GlContext& window;  // current, rendered and finished
  int x = 0, y = 0;
};

// Copies tile `p` from `from` into `frame` (fb_width RGB pixels a row, rows top to bottom) at
// its packed place; for DEPTH the depth too, a depth `far_as` replacing the far plane: layer 0
// of a depth wall sends its cleared pixels one step nearer, so the scene's clear colour shows
// where no layer draws, as in a whole-frame render, yet behind every fragment one would keep
// (the camera keeps the scene well inside the far plane). The caller checks the frame's size.
void copy_tile_out(const PackedTile& p, const TileInWindow& from, std::uint32_t far_as,
                   std::span<std::uint8_t> frame, int fb_width);

// The scanlines of every DEPTH tile of `plan` in `frame`, packed and with their headers drawn
// for `frame_parity`, rewritten as sparse rows (tilelayout/sparse_depth.hpp): DEPTH strips over
// what `skip` may not leave out, a SKIP over the rest. The mesh then composites only those.
void sparse_depth_rows(const PipeserverPlan& plan, bool frame_parity, const DepthSkip& skip,
                       std::span<std::uint8_t> frame, SparseScratch& scratch);

}  // namespace l2
