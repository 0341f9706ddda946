// Fixtures for the pipeserver tests: a small wall built in code, routing of scanned-out frames
// back into displays with the spec §3 parser, and image comparison; and whether AddressSanitizer
// instruments the build, for the tests that do less under it.
#pragma once

#include <vector>

#include "image/rgb_image.hpp"
#include "pipeserver/scene.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2::test {

// Two 64x48 displays side by side with an 8-pixel mullion (canvas 136x48), cut into a grid of
// tile_w x tile_h logical tiles, split at display edges, dealt round-robin to `pipeservers`
// pipeservers with fb_w x fb_h framebuffers.
TileLayout small_layout(int pipeservers, int tile_w, int tile_h, int fb_w, int fb_h);

struct Reassembly {
  std::vector<RgbImage> displays;
  StripErrorCounts errors;
  long copies = 0;
  long copied_pixels = 0;
  long composited_pixels = 0;      // of KEY and DEPTH strips
  std::vector<int> parities_seen;  // frame bit of every COPY/SKIP header, once per value seen
};

// Routes every COPY strip of every frame to its display, as the emulator would; KEY and DEPTH
// strips are only counted (check_wall routes walls with them through the emulator).
Reassembly reassemble(const Wall& wall, const std::vector<RgbImage>& frames);

struct ImageDiff {
  long pixels_differing = 0;   // any channel differs
  long pixels_beyond_one = 0;  // some channel differs by more than 1 (coverage or depth order)
  int max_channel_diff = 0;
  long at_tile_edges = 0;  // differing pixels on the first or last row/column of a tile
  ImageDiff& operator+=(const ImageDiff& o);
};
ImageDiff compare(const RgbImage& a, const RgbImage& b);
// The pixels of `image` in `r` (inside it).
RgbImage crop(const RgbImage& image, const Rect& r);
// Also counts differing pixels on the border rows/columns of the display's tiles.
ImageDiff compare(const RgbImage& a, const RgbImage& b, const TileLayout& layout, int display);

// Renders `frame` on every pipeserver of the layout, routes the frames (through the emulator's
// router when the wall composites) and compares every display with its reference render.
struct WallCheck {
  Reassembly reassembly;
  std::vector<ImageDiff> diffs;  // per display
  long display_pixels = 0;       // sum of display areas
};
// locate_edges also fills ImageDiff::at_tile_edges (slower; for the measurement tool).
WallCheck check_wall(const TileLayout& layout, Scene& scene, int frame, bool locate_edges = false);

// Small, quick versions of every scene.
SceneOptions small_options();

// Whether AddressSanitizer instruments this build: GCC says so with __SANITIZE_ADDRESS__, Clang
// through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace l2::test
