#include "balance/balancer.hpp"

#include <algorithm>

#include "balance/assign_heaviest.hpp"
#include "balance/kd_cost_grid.hpp"
#include "tilelayout/planner.hpp"

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
  return s;
}

Balancer::Balancer(const Wall& wall, BalanceSettings settings) : wall_(wall), settings_(settings) {
  const bool balancing = settings.mode != BalanceMode::Static || settings.assign;
  if (balancing && (wall.depth_layers != 0 || wall.overlay)) {
    throw LayoutError(fmt::format(
        "{}balance.mode: {} needs a sort-first wall without [depth] "
        "or [overlay]",
        wall.source.empty() ? "" : wall.source.string() + ": ", to_string(settings.mode)));
  }
  Wall first = wall;
  if (settings.mode == BalanceMode::Strips) {
    strips_ = first_strips(wall);
    first = with_list(wall, strips_->tiles());
  } else if (settings.mode == BalanceMode::Kd) {
    first =
        with_kd(wall, wall.tiling.kind == TilingKind::KdSplit ? wall.tiling.cost
                                                              : std::vector<std::vector<double>>{});
  }
  layout_ = plan(first, nullptr);
}

TileLayout Balancer::plan(const Wall& wall, const CostEstimate* estimate) const {
  if (!settings_.assign || estimate == nullptr) return plan_layout(wall);
  std::vector<double> cost;
  for (const Rect& r : make_logical_tiles(wall)) cost.push_back(estimate->cost(r));
  return plan_layout(wall, assign_heaviest_first(cost, wall.pipeserver_count));
}

BalanceStep Balancer::next(const TileSeconds& seconds) {
  const CostEstimate estimate = CostEstimate::from_layout(layout_, seconds);
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
    return {false, e.what()};
  }
  grid_ = std::move(grid);
  const bool changed = planned.logical_tiles != layout_.logical_tiles ||
                       planned.tile_pipeserver != layout_.tile_pipeserver;
  layout_ = std::move(planned);
  return {changed, ""};
}

}  // namespace l2
