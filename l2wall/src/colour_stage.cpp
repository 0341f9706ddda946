#include "l2wall/colour_stage.hpp"

#include "tilelayout/blend_map.hpp"

namespace l2 {

ColourStage::ColourStage(const Wall& wall) {
  for (const Display& d : wall.displays) {
    std::optional<TableMap> map = display_tables(wall, d.id);
    if (!map && !d.colour.applies()) continue;
    if (!tables_) tables_ = std::make_shared<std::map<int, Matched>>();
    Matched& m = (*tables_)[d.id];
    m.table = d.colour.table;
    m.map = std::move(map);
  }
}

DisplayPictures ColourStage::apply(DisplayPictures raw) const {
  if (!tables_) return raw;
  return [tables = tables_, raw = std::move(raw)](int display) -> const RgbImage& {
    const RgbImage& picture = raw(display);
    const auto it = tables->find(display);
    if (it == tables->end() || picture.empty()) return picture;
    Matched& m = it->second;
    if (m.map)
      apply_table_map(*m.map, picture, m.picture);
    else
      apply_colour(m.table, picture, m.picture);
    return m.picture;
  };
}

}  // namespace l2
