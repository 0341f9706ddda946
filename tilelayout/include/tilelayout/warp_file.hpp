// A display's geometry warp as a PFM file (docs/wall-file.md, "Warping projected pictures"), as
// MPCDI's geometryWarpFile is: a 3-channel float picture whose pixels are points spread evenly
// over the display's pixel centres (as many as the display has pixels, or a coarser mesh of at
// least 2x2), each holding in its first two channels the normalised position (x, y) in the
// display's reassembled frame that the output pixel there shows; the third channel is not used.
// Rows are stored bottom to top, as the PFM format defines; a negative scale means little-endian
// floats.
//
// Example:
//   const WarpMap m = parse_warp_pfm(bytes, "calibration/warp-0.pfm", 1024, 768);
//   // refused: "calibration/warp-0.pfm: width: must be 2..1024 points (the display is 1024
//   // wide), got 2000"
#pragma once

#include <cstddef>
#include <string_view>

#include "image/warp_map.hpp"

namespace l2 {

// The header ("PF", width, height, scale, each ended by one blank) is short; a file whose first
// kMaxPfmHeaderBytes hold no complete header is not a PFM warp.
inline constexpr std::size_t kMaxPfmHeaderBytes = 128;

// The most bytes a warp for a width x height display can have: what a reader may read before
// giving up on a larger file.
std::size_t max_warp_pfm_bytes(int width, int height);

// The warp in `bytes`, for a width x height display. Throws LayoutError, one line that starts
// with `name` and names the field: "magic" (not "PF"), "width", "height" (more points than the
// display has pixels, or fewer than 2), "scale" (not a non-zero number), "data" (fewer or more
// bytes than the header declares).
WarpMap parse_warp_pfm(std::string_view bytes, std::string_view name, int width, int height);

}  // namespace l2
