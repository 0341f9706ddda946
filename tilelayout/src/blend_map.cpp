// The ramps are in canvas pixels and the weights in linear light: a display's raw weight at a
// canvas pixel is the product of one factor per ramped edge, min(1, d / width), d the distance
// of the pixel's centre from that edge; the raw weights of the displays showing the pixel are
// then normalised to sum to 1 and taken to 1/kBlendOne by largest remainder, so the integers sum
// to kBlendOne exactly and every display showing the pixel agrees on its share.
#include "tilelayout/blend_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace l2 {
namespace {

bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

// min(1, centre / width), or 1 where the edge has no ramp.
double ramp(double centre, int width) {
  return width == 0 ? 1.0 : std::min(1.0, centre / width);
}

// The displays that can show a pixel of one display (itself and those overlapping it), with
// their rectangles and ramps, worked out once for every pixel of its map.
class Neighbourhood {
 public:
  Neighbourhood(const Wall& wall, const Rect& around) {
    for (const Display& d : wall.displays) {
      if (!overlap(d.on_canvas(), around)) continue;
      members_.push_back({d.id, d.on_canvas(), blend_ramps(wall, d.id)});
    }
    raw_.resize(members_.size());
    share_.resize(members_.size());
  }

  // The shares of canvas pixel (u, v), in member order, summing to kBlendOne when any member
  // shows it.
  const std::vector<int>& shares(int u, int v) {
    double sum = 0;
    for (std::size_t i = 0; i < members_.size(); ++i) {
      const Member& m = members_[i];
      raw_[i] = 0;
      if (!m.rect.contains(u, v)) continue;
      raw_[i] =
          ramp(u - m.rect.x + 0.5, m.ramps.left) * ramp(m.rect.right() - u - 0.5, m.ramps.right) *
          ramp(v - m.rect.y + 0.5, m.ramps.top) * ramp(m.rect.bottom() - v - 0.5, m.ramps.bottom);
      sum += raw_[i];
    }
    int given = 0;
    for (std::size_t i = 0; i < members_.size(); ++i) {
      const double exact = sum > 0 ? raw_[i] / sum * kBlendOne : 0;
      share_[i] = static_cast<int>(std::floor(exact));
      raw_[i] = raw_[i] > 0 ? exact - share_[i] : -1;  // now the remainder; -1: not showing it
      given += share_[i];
    }
    // What flooring left over, one each to the largest remainders (ties: the lower id, which
    // comes first).
    for (int left = sum > 0 ? kBlendOne - given : 0; left > 0; --left) {
      const auto largest = std::max_element(raw_.begin(), raw_.end());
      ++share_[static_cast<std::size_t>(largest - raw_.begin())];
      *largest = -1;
    }
    return share_;
  }

  std::size_t member_of(int display) const {
    for (std::size_t i = 0; i < members_.size(); ++i)
      if (members_[i].id == display) return i;
    return members_.size();
  }

 private:
  struct Member {
    int id;
    Rect rect;
    BlendRamps ramps;
  };
  std::vector<Member> members_;
  std::vector<double> raw_;
  std::vector<int> share_;
};

}  // namespace

BlendRamps blend_ramps(const Wall& wall, int display) {
  BlendRamps ramps;
  const Rect r = wall.displays.at(static_cast<std::size_t>(display)).on_canvas();
  for (const Display& other : wall.displays) {
    const Rect o = other.on_canvas();
    if (other.id == display || !overlap(r, o)) continue;
    // An edge is ramped as deep as the overlap of a display reaching past it.
    if (o.x < r.x) ramps.left = std::max(ramps.left, std::min(o.right(), r.right()) - r.x);
    if (o.right() > r.right()) ramps.right = std::max(ramps.right, r.right() - std::max(o.x, r.x));
    if (o.y < r.y) ramps.top = std::max(ramps.top, std::min(o.bottom(), r.bottom()) - r.y);
    if (o.bottom() > r.bottom())
      ramps.bottom = std::max(ramps.bottom, r.bottom() - std::max(o.y, r.y));
  }
  return ramps;
}

std::vector<int> blend_weights_at(const Wall& wall, int u, int v) {
  std::vector<int> weights(wall.displays.size(), 0);
  Neighbourhood all(wall, {u, v, 1, 1});
  const std::vector<int>& shares = all.shares(u, v);
  for (const Display& d : wall.displays) {
    const std::size_t i = all.member_of(d.id);
    if (i < shares.size()) weights[static_cast<std::size_t>(d.id)] = shares[i];
  }
  return weights;
}

std::vector<std::uint16_t> blend_weights(const Wall& wall, int display) {
  if (!wall.blend.on || !blend_ramps(wall, display).any()) return {};
  const Display& d = wall.displays.at(static_cast<std::size_t>(display));
  Neighbourhood near(wall, d.on_canvas());
  const std::size_t self = near.member_of(display);
  const PanelMap m = d.panel_map();
  std::vector<std::uint16_t> weights(static_cast<std::size_t>(d.width) * d.height);
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      weights[static_cast<std::size_t>(y) * d.width + x] =
          static_cast<std::uint16_t>(near.shares(m.u(x, y), m.v(x, y))[self]);
    }
  }
  return weights;
}

ColourTable blend_table(int weight, double gamma) {
  const double gain = std::pow(static_cast<double>(weight) / kBlendOne, 1.0 / gamma);
  return colour_table_from_gain({gain, gain, gain}, {0, 0, 0});
}

std::optional<TableMap> display_tables(const Wall& wall, int display) {
  std::vector<std::uint16_t> weights = blend_weights(wall, display);
  if (weights.empty()) return std::nullopt;
  const Display& d = wall.displays.at(static_cast<std::size_t>(display));
  TableMap map{d.width, d.height, std::move(weights), {}};
  // Each weight that occurs becomes one table, blend first, then the display's colour matching
  // (docs/wall-file.md says why in that order); the map keeps the table's index.
  std::vector<int> table_of(kBlendOne + 1, -1);
  for (std::uint16_t& w : map.index) {
    int& t = table_of[w];
    if (t < 0) {
      t = static_cast<int>(map.tables.size());
      map.tables.push_back(compose(blend_table(w, wall.blend.gamma), d.colour.table));
    }
    w = static_cast<std::uint16_t>(t);
  }
  return map;
}

}  // namespace l2
