#include "packed_rows.hpp"

#include <algorithm>
#include <limits>

namespace l2 {

std::optional<int> needed_height(const std::vector<DisplayTile>& tiles, int width) {
  try {
    return pack_tiles(0, width, std::numeric_limits<int>::max(), tiles).used_height();
  } catch (const LayoutError&) {
    return std::nullopt;
  }
}

std::optional<int> tallest(const std::vector<std::vector<DisplayTile>>& lists, int width) {
  int most = 0;
  for (const auto& list : lists) {
    const std::optional<int> h = needed_height(list, width);
    if (!h) return std::nullopt;
    most = std::max(most, *h);
  }
  return most;
}

}  // namespace l2
