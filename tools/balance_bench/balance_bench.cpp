// balance_bench: how much the load balancer (balance/) shortens frames. Renders a fixed
// camera path on every pipeserver of a wall, in this one process and one pipeserver after the
// other, so each pipeserver's render time is measured alone on a machine whose cores the
// pipeservers of a live run would share. Between frames the balancer plans the next frame's
// layout from the tiles' times, as a live run's coordinator would; as it does, not from frame
// 0's, which carry the renderer's warm-up (far longer than a later frame's; a resisting balancer
// would take a layout that seemed to pay on them and keep it). Prints one CSV row a frame:
// the frame time (the slowest pipeserver's render time: the frame waits for it) and the
// imbalance (that over the mean). Render times are the tiles' CPU times (FrameTimes::tile_ms),
// which other work on the machine does not lengthen. Beside them: the frame time the last
// frame's estimate predicted for this frame's layout, the tiles and the overlap factor.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "balance/balancer.hpp"
#include "balance/frame_load.hpp"
#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/scene_cli.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace {

struct Options {
  std::string wall;
  std::string scene = "strips";
  int frames = 30;
  int pipeservers = 0;  // 0: the wall's count
  std::string mode;     // empty: the wall's [balance] mode
  bool assign = false;
  std::optional<double> resistance, tile_cost;  // unset: the wall's [balance]
  std::optional<double> gain;                   // unset: EdgeMotion's
  bool header = false;
  bool no_footprints = false, verbose = false;
  std::string tiles_csv;  // a row per tile and frame, for finding where the time goes
};

// What the estimate of the last frame said each tile of this one would cost (ms); none at
// frame 0, before anything was measured.
std::vector<std::vector<double>> predicted_ms(const l2::TileLayout& layout,
                                              const std::optional<l2::CostEstimate>& estimate) {
  std::vector<std::vector<double>> out;
  for (const l2::PipeserverPlan& p : layout.pipeservers) {
    auto& tiles = out.emplace_back();
    for (const l2::PackedTile& t : p.tiles)
      tiles.push_back(estimate ? estimate->cost(t.tile.on_canvas) * 1000 : 0.0);
  }
  return out;
}

double slowest_sum(const std::vector<std::vector<double>>& per_pipeserver) {
  double most = 0;
  for (const auto& v : per_pipeserver)
    most = std::max(most, std::accumulate(v.begin(), v.end(), 0.0));
  return most;
}

std::vector<std::unique_ptr<l2::Pipeserver>> pipeservers_of(const l2::TileLayout& layout) {
  std::vector<std::unique_ptr<l2::Pipeserver>> out;
  for (std::size_t s = 0; s < layout.pipeservers.size(); ++s) {
    out.push_back(std::make_unique<l2::Pipeserver>(layout, static_cast<int>(s)));
  }
  return out;
}

int run(const Options& o, const l2::SceneOptions& scene_options) {
  l2::Wall wall = o.wall.empty() ? l2::default_wall() : l2::load_wall(o.wall);
  if (o.pipeservers > 0) wall.pipeserver_count = o.pipeservers;
  l2::BalanceSettings settings = l2::balance_settings(wall);
  if (!o.mode.empty()) settings.mode = *l2::parse_balance_mode(o.mode);
  settings.assign = settings.assign || o.assign;
  settings.resistance = o.resistance.value_or(settings.resistance);
  settings.tile_cost = o.tile_cost.value_or(settings.tile_cost);
  settings.motion.gain = o.gain.value_or(settings.motion.gain);
  l2::Balancer balancer(wall, settings);
  auto scene = l2::make_scene(o.scene, scene_options);
  auto pipeservers = pipeservers_of(balancer.layout());
  if (o.header) {
    std::printf(
        "pipeservers,mode,assign,frame,frame_ms,imbalance,retiled,predicted_ms,tiles,"
        "overlap,resisted\n");
  }
  std::FILE* tiles_out = o.tiles_csv.empty() ? nullptr : std::fopen(o.tiles_csv.c_str(), "a");
  if (!o.tiles_csv.empty() && tiles_out == nullptr)
    throw std::runtime_error("cannot write " + o.tiles_csv);
  std::optional<l2::CostEstimate> estimate;
  for (int k = 0; k < o.frames; ++k) {
    const auto predicted = predicted_ms(balancer.layout(), estimate);
    l2::TileSeconds tile_seconds;
    l2::Footprints footprints;
    long draws = 0, batches = 0;
    for (std::size_t s = 0; s < pipeservers.size(); ++s) {
      auto& ps = pipeservers[s];
      ps->render_frame(k, *scene);
      const l2::FrameTimes& t = ps->last_times();
      std::vector<double>& tiles = tile_seconds.emplace_back();
      for (double ms : t.tile_ms) tiles.push_back(ms / 1000);
      if (!o.no_footprints && footprints.empty()) footprints = t.footprints;
      draws += t.buckets.tile_draws;
      batches += t.buckets.batches;
      for (std::size_t i = 0; tiles_out && i < t.tile_ms.size(); ++i) {
        const l2::Rect& r = ps->plan().tiles[i].tile.on_canvas;
        std::fprintf(tiles_out, "%zu,%s,%d,%d,%zu,%zu,%d,%d,%d,%d,%.4f,%.4f\n", pipeservers.size(),
                     l2::to_string(settings.mode), settings.assign ? 1 : 0, k, s, i, r.x, r.y, r.w,
                     r.h, t.tile_ms[i], predicted[s][i]);
      }
    }
    const l2::FrameLoad load = l2::frame_load(tile_seconds);
    estimate = l2::CostEstimate::from_layout(balancer.layout(), tile_seconds, footprints);
    const std::size_t tile_count = balancer.layout().tiles.size();
    const l2::BalanceStep step =
        k == 0 ? l2::BalanceStep{} : balancer.next(tile_seconds, footprints);
    if (o.verbose)
      std::fprintf(stderr, "frame %d: per triangle %.3g us\n", k, estimate->per_triangle() * 1e6);
    if (!step.rejected.empty()) {
      std::fprintf(stderr, "balance_bench: frame %d: next layout not used: %s\n", k,
                   step.rejected.c_str());
    }
    std::printf("%zu,%s,%d,%d,%.4f,%.4f,%d,%.4f,%zu,%.3f,%d\n", pipeservers.size(),
                l2::to_string(settings.mode), settings.assign ? 1 : 0, k, load.frame_seconds * 1000,
                load.imbalance, step.changed ? 1 : 0, k == 0 ? 0.0 : slowest_sum(predicted),
                tile_count, batches == 0 ? 0.0 : double(draws) / double(batches),
                step.resisted ? 1 : 0);
    if (step.changed) {
      for (auto& ps : pipeservers) ps->set_layout(balancer.layout());
    }
  }
  if (tiles_out) std::fclose(tiles_out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "balance_bench: renders a scene's fixed camera path on every pipeserver of a wall and\n"
      "prints a CSV row per frame: frame time (the slowest pipeserver's render time, ms) and\n"
      "imbalance (slowest over mean), with the wall re-tiled between frames by --mode."};
  Options o;
  l2::SceneOptions scene_options;
  l2::add_wall_option(app, o.wall, "default: the built-in default wall");
  app.add_option("--scene", o.scene, "scene to render")
      ->check(CLI::IsMember(l2::built_in_scene_names()))
      ->capture_default_str();
  app.add_option("--frames", o.frames, "frames of the camera path")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_option("--pipeservers", o.pipeservers, "pipeserver count instead of the wall's")
      ->check(CLI::Range(1, l2::kMaxPipeservers));
  app.add_option("--mode", o.mode, "static, strips or kd (default: the wall's [balance] mode)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(l2::kBalanceModeNames),
                                                     std::end(l2::kBalanceModeNames))));
  app.add_flag("--assign", o.assign,
               "heaviest tile first to the pipeserver that finishes first, instead of the wall's "
               "assignment policy (as [balance] assignment = \"heaviest-first\")");
  app.add_option("--resistance", o.resistance,
                 "take a new layout only when it is predicted to shorten the frame by this "
                 "fraction (0: every one; default: the wall's [balance] resistance)")
      ->check(CLI::Range(0.0, 0.99));
  app.add_option("--tile-cost", o.tile_cost,
                 "the fixed part of a display tile in that prediction, as a fraction of the mean "
                 "tile time (default: the wall's [balance] tile_cost)")
      ->check(CLI::Range(0.0, 0.99));
  app.add_option("--gain", o.gain,
                 "the part of its distance to the balanced cut an edge moves each frame (strips), "
                 "or of the measured cost grid blended in (k-d); default: 0.5")
      ->check(CLI::Range(0.05, 1.0));
  app.add_flag("--header", o.header, "print the CSV header line first");
  app.add_flag("--no-footprints", o.no_footprints,
               "price tiles by their pixels alone, not also by the batches they touch");
  app.add_flag("--verbose", o.verbose, "print each frame's fitted price per triangle (stderr)");
  app.add_option("--tiles", o.tiles_csv,
                 "append a CSV row per tile and frame to FILE: pipeservers, mode, assign, frame, "
                 "pipeserver, tile, x, y, w, h (on the canvas), measured ms, the ms the last "
                 "frame's estimate predicted (0 at frame 0)")
      ->type_name("FILE");
  const auto scene_opts = l2::add_scene_options(app, scene_options);
  app.callback([&] { l2::check_scene_options(scene_opts, o.scene); });
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    return run(o, scene_options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "balance_bench: %s\n", e.what());
    return 1;
  }
}
