// Sparse DEPTH rows (spec §7 with §2's SKIP): a scanline of a packed DEPTH tile sent as DEPTH
// strips over the spans where the pipeserver drew and SKIP over the rest, so that what the mesh
// composites follows the geometry, not the tile's size. The row keeps its 4 + 2w columns, so the
// next header lands where the plan puts it (§7 packing).
//
// A pixel may be left out only where sending it could not change a display pixel (the caller
// says which, DepthSkip): a DEPTH pixel at the far plane never writes (§7: strictly nearer).
// Keeping a pixel is always what a dense row does, so spans may take in skippable pixels.
//
// Pure logic on RGB bytes; no I/O.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "strip_headers/strip_header.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// Columns [x0, x1) of a tile row, sent as one DEPTH strip.
struct DepthSpan {
  int x0 = 0, x1 = 0;
  friend bool operator==(const DepthSpan&, const DepthSpan&) = default;
};

// Which pixels of a DEPTH row may be left out.
struct DepthSkip {
  // Depths at or beyond this are left out: the far plane (FFFFFF) alone is always safe; a
  // pipeserver behind depth layer 0 may leave out one step nearer too (depth_skip_of says why).
  std::uint32_t far_from = 0xFFFFFF;
  // Layer 0: pixels at depth `background_depth` whose colour is `background` are left out, the
  // mesh showing its background there anyway.
  bool skip_background = false;
  std::uint32_t background_depth = 0xFFFFFE;
  std::array<std::uint8_t, 3> background{};
};

// What pipeserver `pipeserver` of `layout` may leave out, the mesh's background (spec §5) being
// `background`. The far plane always. Where the depth layers nest — every DEPTH tile of a
// pipeserver of layer 1 or more lies inside a DEPTH tile of a layer-0 pipeserver of a lower
// index (earlier on the bus), and no two layer-0 DEPTH tiles overlap — more: layer 0 sends its
// clear one step nearer than the far plane (pipeserver/depth_out.hpp), so that pixel is never
// beaten by a depth of FFFFFE or more from behind it, and the other layers leave those out; and
// once they do, layer 0 leaves out its clear where its colour is the background, which the
// display then shows. Either way every display pixel stays what the dense rows give.
DepthSkip depth_skip_of(const TileLayout& layout, int pipeserver,
                        std::array<std::uint8_t, 3> background);

// Gaps between spans shorter than this are sent with them: a strip costs a header, a parse step
// and a run, more than compositing a few pixels that do not write.
inline constexpr int kSparseMergeGap = 16;

// The spans of a row of `w` colour pixels and `w` depth pixels (RGB, three bytes each) to send
// as DEPTH strips, left to right, into `spans` (cleared first). Spans are at least
// kSparseMergeGap apart, and their strips with one SKIP over the columns left always fill the
// row's 4 + 2w columns exactly (where two columns would be left, too few for a SKIP, the one
// span takes the row's one pixel it missed). w >= 1.
void find_depth_spans(const std::uint8_t* colour, const std::uint8_t* depth, int w,
                      const DepthSkip& skip, std::vector<DepthSpan>& spans);

// The framebuffer columns a row of `w` pixels sent as `spans` takes before its SKIP: 4 + 2k per
// span of k pixels.
int sparse_columns(std::span<const DepthSpan> spans);

// Rewrites one scanline of a packed DEPTH tile in place. `gap` points at the tile's gap (its EXT
// header), followed by the dense row: extension word, w colour pixels, w depth pixels. `row`
// is the EXT header of the dense row (display, x, y, width w, frame). Each span becomes an EXT
// header for columns x + x0 .. x + x1 - 1, the DEPTH extension word, its colour and its depth;
// then a SKIP over the columns left, whose pixels are black. `scratch` keeps its capacity
// between calls. Spans must come from find_depth_spans for this row.
void pack_sparse_row(std::uint8_t* gap, const StripHeader& row, std::span<const DepthSpan> spans,
                     std::vector<std::uint8_t>& scratch);

// What a caller of the two above keeps from row to row and frame to frame, so that they
// allocate nothing once warm.
struct SparseScratch {
  std::vector<DepthSpan> spans;
  std::vector<std::uint8_t> row;
};

}  // namespace l2
