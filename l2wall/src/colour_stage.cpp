#include "l2wall/colour_stage.hpp"

namespace l2 {

ColourStage::ColourStage(const Wall& wall) {
  for (const Display& d : wall.displays) {
    if (!d.colour.applies()) continue;
    if (!tables_) tables_ = std::make_shared<std::map<int, Matched>>();
    (*tables_)[d.id].table = d.colour.table;
  }
}

DisplayPictures ColourStage::apply(DisplayPictures raw) const {
  if (!tables_) return raw;
  return [tables = tables_, raw = std::move(raw)](int display) -> const RgbImage& {
    const RgbImage& picture = raw(display);
    const auto it = tables->find(display);
    if (it == tables->end() || picture.empty()) return picture;
    apply_colour(it->second.table, picture, it->second.picture);
    return it->second.picture;
  };
}

}  // namespace l2
