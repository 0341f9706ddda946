#include "l2wall/colour_stage.hpp"

#include "tilelayout/blend_map.hpp"

namespace l2 {

ColourStage::ColourStage(const Wall& wall) {
  for (const Display& d : wall.displays) {
    std::optional<TableMap> map = display_tables(wall, d.id);
    if (!map && !d.colour.applies() && !d.warp_map && !d.level_map) continue;
    if (!tables_) tables_ = std::make_shared<std::map<int, Matched>>();
    Matched& m = (*tables_)[d.id];
    m.warp = d.warp_map;
    m.levels = d.level_map;
    m.colour = d.colour.applies();
    m.table = d.colour.table;
    m.map = std::move(map);
  }
}

DisplayPictures ColourStage::apply(DisplayPictures raw, std::optional<int> frame) const {
  if (!tables_) return raw;
  return [tables = tables_, raw = std::move(raw), frame](int display) -> const RgbImage& {
    const auto it = tables->find(display);
    if (it == tables->end()) return raw(display);
    Matched& m = it->second;
    if (frame && m.frame == frame) return m.picture;
    const RgbImage& picture = raw(display);
    if (picture.empty()) return picture;
    // The warp first: alpha, beta, blend and colour are of the display's own pixels, wherever
    // their light came from in the frame. Each later step then works in place on the picture
    // made.
    const RgbImage* from = &picture;
    if (m.warp) {
      apply_warp(*m.warp, picture, m.picture);
      from = &m.picture;
    }
    if (m.levels) {
      apply_level_map(*m.levels, *from, m.picture);
      from = &m.picture;
    }
    if (m.map)
      apply_table_map(*m.map, *from, m.picture);
    else if (m.colour)
      apply_colour(m.table, *from, m.picture);
    m.frame = frame;
    return m.picture;
  };
}

}  // namespace l2
