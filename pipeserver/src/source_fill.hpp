// Fills a tile from a source picture by the nearest sampling of picture_view.hpp, at level 0
// or one of its MIP levels, reading only the source rows and columns the tile shows.
#pragma once

#include <cstdint>
#include <functional>

#include "image/rgb_image.hpp"
#include "pipeserver/picture_view.hpp"

namespace l2::detail {

// Writes columns [x_begin, x_end) of source row y, as RGB, to `rgb`.
using SourceRows = std::function<void(int y, int x_begin, int x_end, std::uint8_t* rgb)>;

// A MIP level of the source (picture_view.hpp): `rows` then gives that level's rows.
struct SourceLevel {
  int level = 0;
  int width = 0, height = 0;  // the level's sides
};

void fill_from_source(const SourceView& view, int source_width, int source_height,
                      const Canvas& canvas, const Rect& on_canvas, const SourceRows& rows,
                      RgbImage& rgb);
// The same, sampling `level` of the source by the rule of picture_view.hpp.
void fill_from_source(const SourceView& view, int source_width, int source_height,
                      const SourceLevel& level, const Canvas& canvas, const Rect& on_canvas,
                      const SourceRows& rows, RgbImage& rgb);

}  // namespace l2::detail
