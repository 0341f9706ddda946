// Every COPY, KEY and DEPTH strip of a set of scanned-out frames, as the router would find it (spec
// §3): where it sits in its frame, its header and the parser's errors. Private to the verifier.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/strip_header.hpp"
#include "verify/routing_check.hpp"

namespace l2::verify_detail {

struct FoundStrip {
  int input = 0, source_row = 0, source_x = 0;
  int length = 0;       // pixels present in the scanline
  std::uint64_t value;  // the 48-bit header as drawn
  StripHeader header;
  Compositing how = Compositing::Copy;  // KEY and DEPTH: EXT strips (§7)
  std::uint32_t key = 0;                // KEY: the key colour
  int depth_x = 0;                      // DEPTH: column of depth pixel 0 in its frame
};

// COPY, KEY and DEPTH strips of every frame in priority order (inputs ascending, rows top to
// bottom, left to right); fills `inputs` with one InputCheck per frame (strip and error counts,
// where the first refusals were, the frame's size and parity).
// `skips`, when given, gets every SKIP the same way (how Copy): what a sparse DEPTH row passes
// over (tilelayout/sparse_depth.hpp), for the plan check.
std::vector<FoundStrip> find_strips(std::span<const RgbImage> frames,
                                    std::vector<InputCheck>& inputs,
                                    std::vector<FoundStrip>* skips = nullptr);

}  // namespace l2::verify_detail
