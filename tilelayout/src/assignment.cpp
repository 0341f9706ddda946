// Assignment policies: which pipeserver renders which logical tile.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "tilelayout/planner.hpp"

namespace l2 {
namespace {

std::vector<int> raster_order(const std::vector<Rect>& tiles) {
  std::vector<int> order(tiles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::pair(tiles[a].y, tiles[a].x) < std::pair(tiles[b].y, tiles[b].x);
  });
  return order;
}

// Rows are tiles sharing a top edge; every second row runs right to left.
std::vector<int> zigzag_order(const std::vector<Rect>& tiles) {
  std::vector<int> order = raster_order(tiles);
  bool reversed = false;
  for (auto row = order.begin(); row != order.end();) {
    auto end = std::find_if(row, order.end(), [&](int i) { return tiles[i].y != tiles[*row].y; });
    if (reversed) std::reverse(row, end);
    reversed = !reversed;
    row = end;
  }
  return order;
}

// Rings by Chebyshev distance from the canvas centre, measured in median tile sizes so a grid
// tiling gives its natural square rings; within a ring, clockwise from the top-left corner.
std::vector<int> spiral_order(const std::vector<Rect>& tiles, Rect canvas) {
  std::vector<int> ws, hs;
  for (const Rect& t : tiles) {
    ws.push_back(t.w);
    hs.push_back(t.h);
  }
  std::nth_element(ws.begin(), ws.begin() + ws.size() / 2, ws.end());
  std::nth_element(hs.begin(), hs.begin() + hs.size() / 2, hs.end());
  const double tw = ws[ws.size() / 2], th = hs[hs.size() / 2];
  const double cx = canvas.x + canvas.w / 2.0, cy = canvas.y + canvas.h / 2.0;
  constexpr double kPi = 3.14159265358979323846;
  std::vector<std::pair<long, double>> key(tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const double dx = (tiles[i].x + tiles[i].w / 2.0 - cx) / tw;
    const double dy = (tiles[i].y + tiles[i].h / 2.0 - cy) / th;
    const long ring = std::lround(std::max(std::abs(dx), std::abs(dy)));
    // Angle clockwise (y grows down) from the top-left direction, in [0, 2pi).
    double angle = std::atan2(dy, dx) + 3 * kPi / 4;
    if (angle < 0) angle += 2 * kPi;
    if (angle >= 2 * kPi) angle -= 2 * kPi;
    key[i] = {ring, angle};
  }
  std::vector<int> order(tiles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  return order;
}

std::vector<int> deal(const std::vector<int>& order, int pipeservers) {
  std::vector<int> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[order[k]] = static_cast<int>(k % pipeservers);
  return out;
}

}  // namespace

const char* to_string(AssignmentPolicy policy) {
  static const char* const kNames[] = {"round-robin", "zig-zag", "spiral", "blocks",
                                       "area-balanced"};
  return kNames[static_cast<int>(policy)];
}

std::vector<int> assign_pipeservers(AssignmentPolicy policy, const std::vector<Rect>& tiles,
                                    const std::vector<long long>& weights, int pipeserver_count,
                                    Rect canvas) {
  const int n = static_cast<int>(tiles.size());
  if (n == 0) return {};
  switch (policy) {
    case AssignmentPolicy::RoundRobin: {
      std::vector<int> order(n);
      std::iota(order.begin(), order.end(), 0);
      return deal(order, pipeserver_count);
    }
    case AssignmentPolicy::ZigZag:
      return deal(zigzag_order(tiles), pipeserver_count);
    case AssignmentPolicy::Spiral:
      return deal(spiral_order(tiles, canvas), pipeserver_count);
    case AssignmentPolicy::Blocks: {
      const std::vector<int> order = raster_order(tiles);
      std::vector<int> out(n);
      for (int k = 0; k < n; ++k) {
        out[order[k]] = static_cast<int>(static_cast<long long>(k) * pipeserver_count / n);
      }
      return out;
    }
    case AssignmentPolicy::AreaBalanced:
      break;
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return weights[a] > weights[b]; });
  std::vector<long long> load(pipeserver_count, 0);
  std::vector<int> out(n);
  for (int i : order) {
    const int s = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    out[i] = s;
    load[s] += weights[i];
  }
  return out;
}

}  // namespace l2
