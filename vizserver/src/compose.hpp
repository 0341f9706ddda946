// Writing a received tile into a display image: the compositing server's equivalent of the
// emulator's COPY, KEY and DEPTH strips (spec §3, §5, §7). A tile of h rows is h strips, so errors
// are counted per row exactly as the emulator counts them per strip: a row landing partly or wholly
// outside its display is one clip, a row for a display that does not exist is one missing_display.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "image/band_coverage.hpp"
#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz {

// A display's depth plane (spec §7): one value per pixel, row-major; empty for a display that
// receives no DEPTH tile (nothing there compares depths).
using DepthPlane = std::vector<std::uint32_t>;

// Writes the tile's rows (row_bytes() each, `stride` bytes apart, top to bottom) into
// displays[tile.display], clipped to it, as the emulator applies a strip (spec §7): COPY writes
// its colour and depth 0, KEY the same except where a pixel is the key colour, DEPTH its colour
// and depth where strictly nearer than depths[tile.display] holds (a plane made at the far
// depth if the display has none yet). Never writes outside the image, whatever the header.
void compose_tile(std::vector<RgbImage>& displays, std::vector<DepthPlane>& depths,
                  const TileHeader& tile, const std::uint8_t* pixels, std::size_t stride,
                  StripErrorCounts& counts);
// The same for displays without depth planes.
void compose_tile(std::vector<RgbImage>& displays, const TileHeader& tile,
                  const std::uint8_t* pixels, std::size_t stride, StripErrorCounts& counts);

// The display pixels a COPY tile writes, clipped to a display of width x height (a COPY tile
// writes every pixel of its clipped rectangle, whatever its colours); nothing for a KEY or DEPTH
// tile (the background shows through where they write nothing), a tile outside the display or
// a display too large for an Area's 16-bit sides.
std::optional<coverage::Area> copy_area(const TileHeader& tile, int width, int height);

// Paints `background` on the pixels of `display` that no area covers, and only those: a display
// whose COPY tiles cover it is then written once a frame, by its tiles.
void fill_uncovered(RgbImage& display, const std::vector<coverage::Area>& areas, Rgb background,
                    coverage::CoverageScratch& scratch);

}  // namespace l2::viz
