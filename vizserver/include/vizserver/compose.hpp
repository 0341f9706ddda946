// Writing a received tile into a display image: the visualization server's equivalent of the
// emulator's COPY strip (spec §3, §5). A tile of h rows is h strips, so errors are counted per
// row exactly as the emulator counts them per strip: a row landing partly or wholly outside
// its display is one clip, a row for a display that does not exist is one missing_display.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "vizserver/wire.hpp"

namespace l2::viz {

// Copies the tile's rows (w*3 bytes each, `stride` bytes apart, top to bottom) into
// displays[tile.display], clipped to it. Never writes outside the image, whatever the header.
void compose_tile(std::vector<RgbImage>& displays, const TileHeader& tile,
                  const std::uint8_t* pixels, std::size_t stride, StripErrorCounts& counts);

}  // namespace l2::viz
