#include "plan_match.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace l2::verify_detail {
namespace {

// A strip by its place in the frame, and what its header says (parity aside: it changes every
// frame and has a check of its own).
struct Place {
  int row = 0, column = 0;
  auto operator<=>(const Place&) const = default;
};
struct Fields {
  int display = 0, x = 0, y = 0, width = 0;
  bool operator==(const Fields&) const = default;
};
using Strips = std::map<Place, Fields>;

Strips planned(const PipeserverPlan& plan) {
  Strips out;
  for (const PackedTile& p : plan.tiles) {
    const Rect& r = p.tile.on_display;
    for (int j = 0; j < r.h; ++j) out[{p.fb_y + j, p.fb_x}] = {p.tile.display, r.x, r.y + j, r.w};
  }
  return out;
}

Strips found(std::span<const FoundStrip> strips, int input) {
  Strips out;
  for (const FoundStrip& s : strips) {
    if (s.input != input) continue;
    out[{s.source_row, s.source_x}] = {s.header.display, s.header.x, s.header.y, s.header.width};
  }
  return out;
}

StripHeader header_of(const Fields& f) {
  return StripHeader::copy(false, f.display, f.x, f.y, f.width);
}

// How many strips differ between the two, and the first (by row, then column).
long long compare(const Strips& got, const Strips& plan, std::optional<StripDifference>& first) {
  long long differ = 0;
  const auto note = [&](const Place& at, const Fields* g, const Fields* p) {
    ++differ;
    if (first && std::tie(first->row, first->column) <= std::tie(at.row, at.column)) return;
    first = StripDifference{at.row, at.column, g ? std::optional(header_of(*g)) : std::nullopt,
                            p ? std::optional(header_of(*p)) : std::nullopt};
  };
  for (const auto& [at, fields] : got) {
    const auto it = plan.find(at);
    if (it == plan.end() || !(it->second == fields))
      note(at, &fields, it == plan.end() ? nullptr : &it->second);
  }
  for (const auto& [at, fields] : plan) {
    if (!got.contains(at)) note(at, nullptr, &fields);
  }
  return differ;
}

}  // namespace

void match_plans(const TileLayout& layout, std::span<const FoundStrip> strips,
                 std::vector<InputCheck>& inputs) {
  std::vector<Strips> plans;
  for (const PipeserverPlan& p : layout.pipeservers) plans.push_back(planned(p));
  for (InputCheck& input : inputs) {
    const auto i = static_cast<std::size_t>(input.input);
    const Strips got = found(strips, input.input);
    if (i < layout.pipeservers.size()) {
      input.planned_width = layout.pipeservers[i].fb_width;
      input.planned_height = layout.pipeservers[i].fb_height;
    }
    input.not_as_planned =
        compare(got, i < plans.size() ? plans[i] : Strips{}, input.first_difference);
    if (input.not_as_planned == 0 || got.empty()) continue;
    for (std::size_t j = 0; j < plans.size(); ++j) {
      if (j != i && got == plans[j]) input.carries = static_cast<int>(j);
    }
  }
}

}  // namespace l2::verify_detail
