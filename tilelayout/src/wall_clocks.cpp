// [displays]: each display's own refresh clock (clock_ppm) and the house sync that locks them.
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <vector>

#include "wall_sections.hpp"

namespace l2 {
namespace {

// A display slower than half the rate or faster than one and a half times it is no drifting
// clock but another refresh rate; within this range a display retraces at least once in every
// two house periods, which the frame-lock model relies on.
constexpr int kMaxClockPpm = 500000;

// `clock_ppm`: one entry per display (in id order) or, failing that count, one per swap group (in
// ascending group number), which every display of the group takes.
void read_clock_ppm(const TomlFields& f, Wall& wall) {
  const toml::array* list = f.array("clock_ppm");
  if (!list) return;
  std::set<int> group_set;
  for (const Display& d : wall.displays) group_set.insert(d.swap_group);
  const std::vector<int> groups(group_set.begin(), group_set.end());
  const std::size_t n = list->size();
  if (n != wall.displays.size() && n != groups.size()) {
    f.fail("clock_ppm", fmt::format("needs {} entries (one per display) or {} (one per swap "
                                    "group), got {}",
                                    wall.displays.size(), groups.size(), n));
  }
  std::vector<int> ppm(n);
  for (std::size_t i = 0; i < n; ++i) {
    ppm[i] = array_integer(*list->get(i), fmt::format("{}[{}]", f.field("clock_ppm"), i),
                           f.source(), -kMaxClockPpm, kMaxClockPpm);
  }
  for (Display& d : wall.displays) {
    if (n == wall.displays.size()) {
      d.clock_ppm = ppm[static_cast<std::size_t>(d.id)];
    } else {
      const auto g = std::lower_bound(groups.begin(), groups.end(), d.swap_group) - groups.begin();
      d.clock_ppm = ppm[static_cast<std::size_t>(g)];
    }
  }
}

}  // namespace

void read_display_clocks(const TomlFields& top, Wall& wall) {
  const toml::table* table = top.table("displays");
  if (!table) return;
  const TomlFields f(*table, "displays", top.source(), {"clock_ppm", "sync"});
  wall.frame_lock.modelled = true;
  wall.frame_lock.line = f.line();
  wall.frame_lock.house_sync = f.choice("sync", {"free", "house"}, 0) == 1;
  read_clock_ppm(f, wall);
}

}  // namespace l2
