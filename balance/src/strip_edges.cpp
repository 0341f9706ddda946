#include "balance/strip_edges.hpp"

namespace l2 {
namespace {

std::vector<double> even_edges(int size, int cells) {
  std::vector<double> e;
  for (long long i = 0; i <= cells; ++i) e.push_back(double(size * i / cells));
  return e;
}

}  // namespace

StripEdges::StripEdges(int canvas_width, int canvas_height, int strips, int substrips)
    : width_(canvas_width),
      height_(canvas_height),
      rows_(even_edges(canvas_height, strips)),
      columns_(static_cast<std::size_t>(strips), even_edges(canvas_width, substrips)) {}

void StripEdges::step(const CostEstimate& estimate, const EdgeMotion& motion) {
  const int strips = static_cast<int>(columns_.size());
  const Rect canvas{0, 0, width_, height_};
  const std::vector<double> rows = estimate.cuts_y(canvas, strips);
  for (int i = 1; i < strips; ++i) rows_[i] = move_edge(rows_[i], rows[i - 1], motion);
  const std::vector<int> y = pixel_edges(rows_);
  for (int i = 0; i < strips; ++i) {
    const Rect band{0, y[i], width_, y[i + 1] - y[i]};
    if (estimate.cost(band) <= 0) continue;  // nothing measured there: no reason to move
    std::vector<double>& x = columns_[i];
    const int subs = static_cast<int>(x.size()) - 1;
    const std::vector<double> columns = estimate.cuts_x(band, subs);
    for (int j = 1; j < subs; ++j) x[j] = move_edge(x[j], columns[j - 1], motion);
  }
}

std::vector<Rect> StripEdges::tiles() const {
  std::vector<Rect> out;
  const std::vector<int> y = pixel_edges(rows_);
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const std::vector<int> x = pixel_edges(columns_[i]);
    for (std::size_t j = 0; j + 1 < x.size(); ++j) {
      out.push_back({x[j], y[i], x[j + 1] - x[j], y[i + 1] - y[i]});
    }
  }
  return out;
}

}  // namespace l2
