// Fills a tile from a source picture by the nearest sampling of picture_view.hpp, reading only
// the source rows and columns the tile shows.
#pragma once

#include <cstdint>
#include <functional>

#include "image/rgb_image.hpp"
#include "pipeserver/picture_view.hpp"

namespace l2::detail {

// Writes columns [x_begin, x_end) of source row y, as RGB, to `rgb`.
using SourceRows = std::function<void(int y, int x_begin, int x_end, std::uint8_t* rgb)>;

void fill_from_source(const SourceView& view, int source_width, int source_height,
                      const Canvas& canvas, const Rect& on_canvas, const SourceRows& rows,
                      RgbImage& rgb);

}  // namespace l2::detail
