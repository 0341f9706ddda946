#include "balance/balancer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "balance/assign_heaviest.hpp"
#include "balance/kd_cost_grid.hpp"
#include "balance/layout_cost.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/survival.hpp"

namespace l2 {
namespace {

StripEdges first_strips(const Wall& wall) {
  if (wall.tiling.kind == TilingKind::Strips) {
    return {wall.canvas_width, wall.canvas_height, wall.tiling.strip_count,
            wall.tiling.substrip_count};
  }
  const int tiles = static_cast<int>(make_logical_tiles(wall).size());
  const int strips = std::clamp(wall.pipeserver_count, 1, wall.canvas_height);
  return {wall.canvas_width, wall.canvas_height, strips,
          std::clamp(tiles / strips, 1, wall.canvas_width)};
}

Wall with_list(const Wall& wall, std::vector<Rect> tiles) {
  Wall w = wall;
  w.tiling = {};
  w.tiling.kind = TilingKind::List;
  w.tiling.rects = std::move(tiles);
  return w;
}

Wall with_kd(const Wall& wall, std::vector<std::vector<double>> grid) {
  Wall w = wall;
  const int count = wall.tiling.kind == TilingKind::KdSplit
                        ? wall.tiling.tile_count
                        : static_cast<int>(make_logical_tiles(wall).size());
  w.tiling = {};
  w.tiling.kind = TilingKind::KdSplit;
  w.tiling.tile_count = count;
  w.tiling.cost = std::move(grid);
  return w;
}

}  // namespace

std::optional<BalanceMode> parse_balance_mode(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kBalanceModeNames); ++i) {
    if (kBalanceModeNames[i] == name) return static_cast<BalanceMode>(i);
  }
  return std::nullopt;
}

const char* to_string(BalanceMode mode) {
  return kBalanceModeNames[static_cast<int>(mode)].data();
}

BalanceSettings balance_settings(const Wall& wall) {
  BalanceSettings s;
  s.mode = wall.balance.mode;
  s.assign = wall.balance.heaviest_first;
  s.resistance = wall.balance.resistance;
  s.tile_cost = wall.balance.tile_cost;
  return s;
}

namespace {

void check_sort_first(const Wall& wall, const BalanceSettings& settings) {
  const bool balancing = settings.mode != BalanceMode::Static || settings.assign;
  if (balancing && (wall.depth_layers != 0 || wall.overlay)) {
    throw LayoutError(fmt::format(
        "{}balance.mode: {} needs a sort-first wall without [depth] "
        "or [overlay]",
        wall.source.empty() ? "" : wall.source.string() + ": ", to_string(settings.mode)));
  }
}

}  // namespace

Balancer::Balancer(const Wall& wall, BalanceSettings settings) : wall_(wall), settings_(settings) {
  check_sort_first(wall, settings);
  const bool balancing = settings.mode != BalanceMode::Static || settings.assign;
  Wall first = wall;
  if (settings.mode == BalanceMode::Strips) {
    strips_ = first_strips(wall);
    first = with_list(wall, strips_->tiles());
  } else if (settings.mode == BalanceMode::Kd) {
    first =
        with_kd(wall, wall.tiling.kind == TilingKind::KdSplit ? wall.tiling.cost
                                                              : std::vector<std::vector<double>>{});
  }
  if (settings.resistance < 0 || settings.resistance >= 1 || settings.tile_cost < 0 ||
      settings.tile_cost >= 1) {
    throw std::invalid_argument(fmt::format(
        "balance resistance and tile cost are fractions from 0 up to below 1, got {} and {}",
        settings.resistance, settings.tile_cost));
  }
  // Resisting, the wall's own layout stays until a cut is predicted to beat it.
  if (settings.resistance > 0) first = wall;
  try {
    layout_ = plan(first, nullptr);
  } catch (const LayoutError& e) {
    // The mode's first cut may not fit the framebuffers (even strips on a wall of tall
    // displays): the wall's own plan stays, and the steps move the cut on from there.
    if (!balancing) throw;
    first_refused_ = e.what();
    layout_ = plan(wall, nullptr);
  }
}

TileLayout Balancer::plan(const Wall& wall, const CostEstimate* estimate) const {
  if (lost_.empty()) {
    if (!settings_.assign || estimate == nullptr) return plan_layout(wall);
    std::vector<double> cost;
    for (const Rect& r : make_logical_tiles(wall)) cost.push_back(estimate->cost(r));
    return plan_layout(wall, assign_heaviest_first(cost, wall.pipeserver_count));
  }
  // The pipeservers still there, dealt the tiles as if they were the whole wall.
  const std::vector<Rect> logical = make_logical_tiles(wall);
  std::vector<int> of;
  if (settings_.assign && estimate != nullptr) {
    std::vector<int> serving;
    for (int s = 0; s < wall.pipeserver_count; ++s) {
      if (!std::binary_search(lost_.begin(), lost_.end(), s)) serving.push_back(s);
    }
    std::vector<double> cost;
    for (const Rect& r : logical) cost.push_back(estimate->cost(r));
    of = assign_heaviest_first(cost, static_cast<int>(serving.size()));
    for (int& s : of) s = serving[static_cast<std::size_t>(s)];
  } else {
    of = assign_without(wall, logical, wall.assignment, lost_);
  }
  try {
    return plan_layout(wall, of, lost_);
  } catch (const LayoutError&) {
    // Fewer framebuffers hold the same pixels: shared out by visible area they fit more often
    // than by the policy or by cost. The first refusal is the one to report.
    try {
      return plan_layout(wall, assign_without(wall, logical, AssignmentPolicy::AreaBalanced, lost_),
                         lost_);
    } catch (const LayoutError&) {
    }
    throw;
  }
}

void Balancer::switch_mode(BalanceMode mode) {
  BalanceSettings next = settings_;
  next.mode = mode;
  check_sort_first(wall_, next);
  if (mode == BalanceMode::Strips && settings_.mode != BalanceMode::Strips)
    strips_ = first_strips(wall_);
  if (mode == BalanceMode::Kd && settings_.mode != BalanceMode::Kd) grid_.clear();
  settings_ = next;
}

void Balancer::lose_pipeserver(int pipeserver) {
  if (pipeserver < 0 || pipeserver >= wall_.pipeserver_count) {
    throw std::invalid_argument(
        fmt::format("pipeserver {} is not 0..{}", pipeserver, wall_.pipeserver_count - 1));
  }
  if (std::binary_search(lost_.begin(), lost_.end(), pipeserver)) return;
  if (static_cast<int>(lost_.size()) + 1 >= wall_.pipeserver_count) {
    throw std::invalid_argument(
        fmt::format("pipeserver {} was the last one rendering: no pipeserver is left", pipeserver));
  }
  std::vector<int> lost = lost_;
  lost.insert(std::upper_bound(lost.begin(), lost.end(), pipeserver), pipeserver);
  // The wall's own tiling without it is the last resort of every later step: when that does not
  // fit, the run must not say it goes on and end a frame later.
  try {
    plan_without(wall_, lost);
  } catch (const LayoutError& e) {
    throw LayoutError(
        fmt::format("the other pipeservers' framebuffers cannot hold pipeserver {}'s tiles: {}",
                    pipeserver, e.what()));
  }
  lost_ = std::move(lost);
}

TileSeconds Balancer::with_stand_ins(const TileSeconds& seconds) const {
  if (lost_.empty()) return seconds;
  TileSeconds out = seconds;
  out.resize(layout_.pipeservers.size());
  double measured = 0, pixels = 0;
  for (std::size_t s = 0; s < out.size(); ++s) {
    if (std::binary_search(lost_.begin(), lost_.end(), static_cast<int>(s))) continue;
    const auto& tiles = layout_.pipeservers[s].tiles;
    for (std::size_t i = 0; i < tiles.size() && i < out[s].size(); ++i) {
      measured += std::max(out[s][i], 0.0);
      pixels += double(tiles[i].tile.on_canvas.area());
    }
  }
  const double per_pixel = pixels > 0 ? measured / pixels : 0;
  for (const int s : lost_) {
    auto& times = out[static_cast<std::size_t>(s)];
    times.clear();
    for (const PackedTile& t : layout_.pipeservers[static_cast<std::size_t>(s)].tiles)
      times.push_back(per_pixel * double(t.tile.on_canvas.area()));
  }
  return out;
}

BalanceStep Balancer::next(const TileSeconds& seconds, const Footprints& footprints) {
  const CostEstimate estimate =
      CostEstimate::from_layout(layout_, with_stand_ins(seconds), footprints);
  BalanceStep step;
  step.per_triangle = estimate.per_triangle();
  Wall next = wall_;
  const std::optional<StripEdges> old_strips = strips_;
  std::vector<std::vector<double>> grid;
  if (settings_.mode == BalanceMode::Strips) {
    strips_->step(estimate, settings_.motion);
    next = with_list(wall_, strips_->tiles());
  } else if (settings_.mode == BalanceMode::Kd) {
    grid = blend_grids(
        grid_, kd_cost_grid(wall_, estimate, settings_.kd_grid_columns, settings_.kd_grid_rows),
        settings_.motion.gain);
    next = with_kd(wall_, grid);
  }
  TileLayout planned;
  try {
    planned = plan(next, &estimate);
  } catch (const LayoutError& e) {
    strips_ = old_strips;
    const auto holding = std::find_if(lost_.begin(), lost_.end(), [&](int s) {
      return !layout_.pipeservers[static_cast<std::size_t>(s)].tiles.empty();
    });
    if (holding == lost_.end()) {
      step.rejected = e.what();
      return step;
    }
    // The layout in use still has a lost pipeserver's tiles: it cannot stay. The last resort
    // is the wall's own tiling shared out by its policy or by visible area (what tilelayout's
    // survival counts on); the balancing goes on from there.
    try {
      planned = plan_without(wall_, lost_);
    } catch (const LayoutError&) {
      throw LayoutError(
          fmt::format("the other pipeservers' framebuffers cannot hold pipeserver {}'s tiles: {}",
                      *holding, e.what()));
    }
  }
  grid_ = std::move(grid);
  const bool changed = planned.logical_tiles != layout_.logical_tiles ||
                       planned.tile_pipeserver != layout_.tile_pipeserver;
  if (!changed) return step;
  step.predicted_ratio = predicted_ratio(planned, seconds, footprints);
  // A layout still giving a lost pipeserver tiles cannot stay, whatever the change gains.
  step.resisted =
      lost_.empty() && settings_.resistance > 0 && step.predicted_ratio > 1 - settings_.resistance;
  if (step.resisted) return step;
  layout_ = std::move(planned);
  step.changed = true;
  return step;
}

Balancer::Pricing Balancer::pricing(const TileSeconds& seconds,
                                    const Footprints& footprints) const {
  const TileSeconds measured = with_stand_ins(seconds);
  const double overhead = tile_overhead(measured, settings_.tile_cost);
  return {pixel_estimate(layout_, measured, overhead, footprints), overhead};
}

FramePrediction Balancer::predicted(const TileLayout& candidate, const TileSeconds& seconds,
                                    const Footprints& footprints) const {
  const Pricing p = pricing(seconds, footprints);
  return predict_frame(candidate, p.estimate, p.overhead);
}

double Balancer::predicted_ratio(const TileLayout& candidate, const TileSeconds& seconds,
                                 const Footprints& footprints) const {
  const Pricing p = pricing(seconds, footprints);
  const double now = predict_frame(layout_, p.estimate, p.overhead).slowest;
  return now > 0 ? predict_frame(candidate, p.estimate, p.overhead).slowest / now : 1;
}

}  // namespace l2
