#include "network_needs.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "lightning2_emu/mesh.hpp"

namespace l2 {
namespace {

struct ColumnNeeds {
  std::set<int> displays, inputs;
  double scanned_out = 0, own_strips = 0;  // bytes a frame
};

double gbit_per_s(double bytes, int hz) {
  return bytes * 8 * hz / 1e9;
}

}  // namespace

std::string format_network_needs(const TileLayout& layout) {
  std::map<int, ColumnNeeds> columns;
  for (const PipeserverPlan& plan : layout.pipeservers) {
    const double frame = 3.0 * plan.fb_width * plan.fb_height;
    for (const PackedTile& t : plan.tiles) {
      ColumnNeeds& c = columns[Mesh::column_of_display(t.tile.display)];
      c.displays.insert(t.tile.display);
      if (c.inputs.insert(plan.pipeserver).second) c.scanned_out += frame;
      c.own_strips += 3.0 * (gap_columns(t.tile) + payload_columns(t.tile)) * t.tile.on_display.h;
    }
  }
  const int hz = layout.wall.refresh_hz;
  std::string out = fmt::format(
      "network across machines (l2wall run --mpi), at {} Hz: only rows that changed travel, "
      "compressed; the summary of a run says what went on the wire\n",
      hz);
  for (const auto& [column, c] : columns) {
    out += fmt::format(
        "  board column {} (displays {}): {} input{}, {:.2f} MB a frame as scanned out "
        "({:.2f} Gbit/s); its own strips {:.2f} MB ({:.2f} Gbit/s), the most that changes\n",
        column, fmt::join(c.displays, ","), c.inputs.size(), c.inputs.size() == 1 ? "" : "s",
        c.scanned_out / 1e6, gbit_per_s(c.scanned_out, hz), c.own_strips / 1e6,
        gbit_per_s(c.own_strips, hz));
  }
  return out;
}

}  // namespace l2
