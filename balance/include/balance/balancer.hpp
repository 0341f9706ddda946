// The layout of the next frame from the render times of the last: `[balance] mode` of a wall
// file. Every layout it hands out has passed tilelayout's planner (tiles fit their
// framebuffers, every pipeserver has a tile); one that would not is not used, and the step
// says why.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "balance/cost_estimate.hpp"
#include "balance/edge_motion.hpp"
#include "balance/layout_cost.hpp"
#include "balance/strip_edges.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// BalanceMode (tilelayout/wall.hpp) by its wall-file name ("static", "strips", "kd"); nullopt
// for anything else.
std::optional<BalanceMode> parse_balance_mode(std::string_view name);
const char* to_string(BalanceMode mode);

struct BalanceSettings {
  BalanceMode mode = BalanceMode::Static;
  bool assign = false;  // heaviest tile first to the pipeserver that finishes first, instead
                        // of the wall's assignment policy
  EdgeMotion motion;    // strip edges, and the blending of the k-d cost grid
  int kd_grid_columns = 32, kd_grid_rows = 32;
  // Resistance (Equalizer's issue #186): a new layout is taken only when it is predicted to
  // shorten the frame by at least this fraction of the last one; 0 takes every new layout.
  // With it a balancing mode starts from the wall's own layout, and its cut replaces that only
  // once it pays.
  double resistance = 0;
  // The fixed part of a display tile in that prediction, as a fraction (0 up to below 1) of the
  // last frame's mean tile time: what a cut into more tiles costs beyond its pixels
  // (layout_cost.hpp).
  double tile_cost = 0;
};

// What the wall's [balance] asks for, with the default motion and grid.
BalanceSettings balance_settings(const Wall& wall);

struct BalanceStep {
  bool changed = false;   // the next frame's tiles or their pipeservers differ
  std::string rejected;   // the planner's error when the new layout did not fit; the old stays
  bool resisted = false;  // a new layout was planned but not taken: it would not pay
  // The predicted frame time of the layout planned, over the last frame's (1: the same; below
  // 1: shorter); 1 when nothing new was planned.
  double predicted_ratio = 1;
  // The price per triangle of a batch a tile touches, fitted to the frame (0 without
  // footprints, or when the tiles' times do not show one).
  double per_triangle = 0;
};

class Balancer {
 public:
  // The first frame's layout: the wall's (static, kd) or even strips (strips mode: the
  // wall's strip counts, or one strip per pipeserver cut into as many sub-strips as it has
  // tiles per pipeserver). When that first cut does not fit the framebuffers, the wall's own
  // plan is the first layout and first_refused() says why. Throws LayoutError when the wall
  // cannot be planned, or when a balancing mode meets a depth or overlay wall (their tiles are
  // shared by layers, not by cost).
  Balancer(const Wall& wall, BalanceSettings settings);

  const TileLayout& layout() const { return layout_; }
  // Why the mode's first cut is not the first layout, or empty.
  const std::string& first_refused() const { return first_refused_; }
  const BalanceSettings& settings() const { return settings_; }

  // Frame k's render times, measured on layout(): makes layout() frame k+1's (with resistance,
  // only when the new layout pays; else layout() stays, while the cut moves on). A lost
  // pipeserver's times are not read (it measured nothing): its tiles count at the mean cost per
  // pixel of the others'. While the layout still gives a lost pipeserver tiles it cannot stay:
  // when the next one does not fit the others' framebuffers, the wall's own tiling shared out
  // by its policy or visible area is tried (plan_without, tilelayout/survival.hpp), and when
  // that does not fit either, throws LayoutError.
  // `footprints`: the scene's batches that frame (FrameTimes::footprints of any pipeserver), so
  // that a tile is priced for the batches it touches; none prices pixels alone.
  BalanceStep next(const TileSeconds& seconds, const Footprints& footprints = {});

  // Pipeserver `pipeserver` died: from the next step on it gets no tile, the others share them
  // (by the wall's assignment policy over them, or heaviest first). Throws
  // std::invalid_argument for a pipeserver out of range or the last one left, and LayoutError,
  // the loss not taken, when the wall's own tiling does not fit the others' framebuffers
  // (tilelayout's survival: the wall survives fewer losses).
  void lose_pipeserver(int pipeserver);
  const std::vector<int>& lost() const { return lost_; }  // ascending

  // The slowest pipeserver's predicted time on `candidate` at the costs `seconds` measured on
  // layout() (a frame's times, as next() takes them): what another layout, the wall's own, would
  // have taken on the same frame, and every pipeserver's time summed (the frame's render work).
  // On layout() itself they are the slowest and the sum measured.
  FramePrediction predicted(const TileLayout& candidate, const TileSeconds& seconds,
                            const Footprints& footprints = {}) const;

  // From the next step on, cut by `mode` (a live run's control page switches it): strips start
  // from even strips, kd from the costs the next step measures, static plans the wall's own
  // tiling. Throws LayoutError for a balancing mode on a depth or overlay wall, as the
  // constructor does.
  void switch_mode(BalanceMode mode);

 private:
  // What the last frame's tile times, measured on layout(), say a tile costs: by its pixels
  // (and footprints), plus a fixed part a tile.
  struct Pricing {
    CostEstimate estimate;
    double overhead = 0;
  };
  Pricing pricing(const TileSeconds& seconds, const Footprints& footprints) const;
  TileLayout plan(const Wall& wall, const CostEstimate* estimate) const;
  // The predicted frame time of `candidate` over the last frame's, measured on layout().
  double predicted_ratio(const TileLayout& candidate, const TileSeconds& seconds,
                         const Footprints& footprints) const;
  TileSeconds with_stand_ins(const TileSeconds& seconds) const;

  Wall wall_;
  BalanceSettings settings_;
  std::optional<StripEdges> strips_;
  std::vector<std::vector<double>> grid_;  // kd: the blended cost grid
  TileLayout layout_;
  std::string first_refused_;
  std::vector<int> lost_;
};

}  // namespace l2
