#include "source_fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace l2::detail {

void fill_from_source(const SourceView& view, int source_width, int source_height,
                      const Canvas& canvas, const Rect& on_canvas, const SourceRows& rows,
                      RgbImage& rgb) {
  fill_from_source(view, source_width, source_height, {0, source_width, source_height}, canvas,
                   on_canvas, rows, rgb);
}

void fill_from_source(const SourceView& view, int source_width, int source_height,
                      const SourceLevel& level, const Canvas& canvas, const Rect& on_canvas,
                      const SourceRows& rows, RgbImage& rgb) {
  if (rgb.width() != on_canvas.w || rgb.height() != on_canvas.h) {
    rgb = RgbImage(on_canvas.w, on_canvas.h);
  }
  // The tile's source columns, and the span of the source row that holds them all.
  std::vector<long> columns(static_cast<std::size_t>(on_canvas.w));
  long first = level.width, last = -1;
  for (int i = 0; i < on_canvas.w; ++i) {
    const long sx =
        level_index(source_index(view.centre_x, view.scale_x, canvas.width, on_canvas.x + i),
                    source_width, level.level, level.width);
    columns[static_cast<std::size_t>(i)] = sx;
    if (sx >= 0) {
      first = std::min(first, sx);
      last = std::max(last, sx);
    }
  }
  std::vector<std::uint8_t> span(last >= first ? static_cast<std::size_t>(last - first + 1) * 3
                                               : 0);
  long span_row = -1;  // the source row in `span`
  for (int j = 0; j < on_canvas.h; ++j) {
    std::uint8_t* out = rgb.row(j).data();
    const long sy =
        level_index(source_index(view.centre_y, view.scale_y, canvas.height, on_canvas.y + j),
                    source_height, level.level, level.height);
    if (span.empty() || sy < 0) {
      std::memset(out, 0, rgb.stride());
      continue;
    }
    if (sy != span_row) {
      rows(static_cast<int>(sy), static_cast<int>(first), static_cast<int>(last + 1), span.data());
      span_row = sy;
    }
    for (int i = 0; i < on_canvas.w; ++i) {
      const long sx = columns[static_cast<std::size_t>(i)];
      if (sx < first || sx > last) {
        std::memset(out + 3 * i, 0, 3);
      } else {
        std::memcpy(out + 3 * i, span.data() + 3 * (sx - first), 3);
      }
    }
  }
}

}  // namespace l2::detail
