// Depth compositing (spec §7), sort-last and hybrid: every display tile rendered as `layers`
// DEPTH layers, each by a different input, packed by tilelayout (pack_tiles, draw_headers) into
// input frames of fb_width x fb_height. Layer colours are pattern(input, x, y), depths a
// function of the pixel and the layer with ties, so the composite is known: least depth, of
// equal depths the lower input (the earlier on the bus).
//
// At full coverage every layer draws every pixel. At a lower coverage each layer draws a disc
// of that share of the display about its centre and clears the rest to the far plane; its rows
// go out sparse as a pipeserver sends them (tilelayout/sparse_depth.hpp: DEPTH over the disc,
// SKIP over the rest), and the display shows the background outside the disc. Both coverages
// are timed in alternation with memcpy of the payload bytes each reads (colour and depth pixels
// sent), and the lower coverage's time is given as a share of the full one's, pair by pair.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#include "bench_common.hpp"
#include "lightning2_emu/frame_builder.hpp"
#include "lightning2_emu/mesh.hpp"
#include "tilelayout/sparse_depth.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2bench {
namespace {

struct DepthScenario {
  const char* name;
  std::vector<l2::DisplaySpec> displays;
  int inputs, layers;  // tile of display d is layer k of input (d + k) % inputs
  int fb_width, fb_height;
};

std::uint32_t layer_depth(int input, int x, int y) {
  return static_cast<std::uint32_t>((x * 7 + y * 13 + input * 5) % 6) * 0x20000u;
}

// Whether pixel (x, y) of a w x h display is drawn at `coverage` (0..1]: every pixel at 1, else
// the disc of coverage * w * h pixels about the display's centre.
bool drawn(int x, int y, int w, int h, double coverage) {
  if (coverage >= 1) return true;
  const double dx = x + 0.5 - w / 2.0, dy = y + 0.5 - h / 2.0;
  return dx * dx + dy * dy <= coverage * w * h / M_PI;
}

struct DepthBuilt {
  Built b;  // input_bytes, routed_bytes: the payload bytes read (colour and depth pixels sent)
  std::vector<l2::RgbImage> expected;
};

// One layer's tile in its frame: drawn pixels with their pattern and depth, the rest black at
// the far plane; then its rows sparse. Returns the payload bytes sent.
std::size_t draw_tile(const l2::PackedTile& p, int input, double coverage, l2::RgbImage& fb,
                      l2::SparseScratch& scratch) {
  const l2::Rect& r = p.tile.on_display;
  for (int y = 0; y < r.h; ++y) {
    for (int x = 0; x < r.w; ++x) {
      const bool on = drawn(r.x + x, r.y + y, r.w, r.h, coverage);
      fb.set(p.fb_x + x, p.fb_y + y,
             on ? l2::testing::pattern(input, r.x + x, r.y + y) : l2::Rgb{});
      const std::uint32_t dp = on ? layer_depth(input, r.x + x, r.y + y) : 0xFFFFFF;
      fb.set(p.fb_x + r.w + x, p.fb_y + y,
             {static_cast<std::uint8_t>(dp >> 16), static_cast<std::uint8_t>(dp >> 8),
              static_cast<std::uint8_t>(dp)});
    }
  }
  std::size_t sent = 0;
  l2::StripHeader row = l2::StripHeader::copy(false, p.tile.display, r.x, r.y, r.w);
  row.op = l2::StripOp::Ext;
  for (int y = 0; y < r.h; ++y) {
    std::uint8_t* colour = fb.data() + static_cast<std::size_t>(p.fb_y + y) * fb.stride() +
                           static_cast<std::size_t>(p.fb_x) * 3;
    l2::find_depth_spans(colour, colour + static_cast<std::size_t>(r.w) * 3, r.w, {},
                         scratch.spans);
    row.y = static_cast<std::uint16_t>(r.y + y);
    l2::pack_sparse_row(colour - 3 * l2::gap_columns(p.tile), row, scratch.spans, scratch.row);
    for (const l2::DepthSpan& s : scratch.spans) sent += static_cast<std::size_t>(s.x1 - s.x0) * 6;
  }
  return sent;
}

DepthBuilt build(const DepthScenario& s, double coverage) {
  std::vector<std::vector<l2::DisplayTile>> tiles(s.inputs);
  for (std::size_t d = 0; d < s.displays.size(); ++d) {
    for (int k = 0; k < s.layers; ++k) {
      l2::DisplayTile t;
      t.display = s.displays[d].id;
      t.on_display = {0, 0, s.displays[d].width, s.displays[d].height};
      t.on_canvas = t.on_display;
      t.compositing = l2::Compositing::Depth;
      tiles[(static_cast<int>(d) + k) % s.inputs].push_back(t);
    }
  }
  DepthBuilt out;
  Built& b = out.b;
  b.input_bytes.assign(s.inputs, 0);
  l2::SparseScratch scratch;
  for (int i = 0; i < s.inputs; ++i) {
    const l2::PipeserverPlan plan = l2::pack_tiles(i, s.fb_width, s.fb_height, tiles[i]);
    b.frames.emplace_back(s.fb_width, s.fb_height);
    l2::draw_headers(plan, false, b.frames.back());
    for (const l2::PackedTile& p : plan.tiles) {
      b.input_bytes[i] += draw_tile(p, i, coverage, b.frames.back(), scratch);
    }
    b.routed_bytes += b.input_bytes[i];
  }
  for (const auto& f : b.frames) b.views.push_back(l2::InputFrame::of(f));
  for (std::size_t d = 0; d < s.displays.size(); ++d) {
    const int w = s.displays[d].width, h = s.displays[d].height;
    l2::RgbImage e(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!drawn(x, y, w, h, coverage)) continue;  // the background, black
        int best = -1;
        for (int k = 0; k < s.layers; ++k) {
          const int in = (static_cast<int>(d) + k) % s.inputs;
          if (best < 0 || layer_depth(in, x, y) < layer_depth(best, x, y) ||
              (layer_depth(in, x, y) == layer_depth(best, x, y) && in < best)) {
            best = in;
          }
        }
        e.set(x, y, l2::testing::pattern(best, x, y));
      }
    }
    out.expected.push_back(std::move(e));
  }
  return out;
}

// One coverage of a scenario: its frames, a router and the memcpy of its payload bytes.
struct Case {
  DepthBuilt built;
  CopySameBytes memcpy_same;
  double router_mib = 0;  // the heap's growth across the router's making and first frames
  std::unique_ptr<l2::Router> router_owned;
  l2::Router& router;
  Samples route, copy_same;
  Case(const DepthScenario& s, double coverage, l2::WorkerPool& pool)
      : built(build(s, coverage)),
        memcpy_same(built.b, pool, false),
        router_mib(heap_mib()),
        router_owned(std::make_unique<l2::Router>(
            l2::Mesh::fit(s.inputs, static_cast<int>(s.displays.size()), {s.fb_width, s.fb_height}),
            s.displays, pool)),
        router(*router_owned) {
    for (int warm = 0; warm < 3; ++warm) router.route(built.b.views);
    router_mib = heap_mib() - router_mib;
  }
  void check(const DepthScenario& s, int percent) {
    for (std::size_t d = 0; d < s.displays.size(); ++d) {
      if (router.display(static_cast<int>(d)).back() != built.expected[d]) {
        fmt::print(stderr, "{} at {}% coverage: display {} composited wrong\n", s.name, percent,
                   s.displays[d].id);
        std::exit(1);
      }
    }
  }
  void print(int percent, int workers) const {
    const Built& b = built.b;
    fmt::print(
        "  {:3d}% coverage: {:.1f} MB of payload read per frame (colour and depth), emulator "
        "memory {:.1f} MiB\n"
        "    {} worker(s): compositing {:5.2f} GB/s = {:6.1f} frames/s | memcpy same bytes "
        "{:5.2f} GB/s | compositing/memcpy: fastest runs {:.2f}, median of pairs {:.2f}, by CPU "
        "time {:.2f}\n",
        percent, double(b.routed_bytes) / 1e6, router_mib, workers,
        gbps(b.routed_bytes, route.best()), 1.0 / route.best(),
        gbps(b.routed_bytes, copy_same.best()), copy_same.best() / route.best(),
        median_ratio(copy_same, route, &Time::wall), median_ratio(copy_same, route, &Time::cpu));
  }
};

struct DepthFigures {
  double full_over_memcpy;  // memcpy / compositing time at full coverage, median of pairs
  double part_over_full;    // compositing time at the lower coverage / at full, median of pairs
};

DepthFigures run_depth(const DepthScenario& s, int percent, int repetitions, int workers) {
  l2::WorkerPool pool(workers);
  Case full(s, 1.0, pool);
  Case part(s, percent / 100.0, pool);
  for (int r = -1; r < repetitions; ++r) {
    for (Case* c : {&full, &part}) {
      const Time route_t = timed([&] { c->router.route(c->built.b.views); });
      const Time memcpy_t = timed(c->memcpy_same);
      if (r < 0) continue;
      c->route.runs.push_back(route_t);
      c->copy_same.runs.push_back(memcpy_t);
    }
  }
  full.check(s, 100);
  part.check(s, percent);
  fmt::print("\n{}: {} inputs of {}x{} -> {} display(s), {} DEPTH layer(s) a display\n", s.name,
             s.inputs, s.fb_width, s.fb_height, s.displays.size(), s.layers);
  full.print(100, workers);
  part.print(percent, workers);
  const double share = 1.0 / median_ratio(full.route, part.route, &Time::wall);
  fmt::print(
      "    {}% coverage / full coverage: median of pairs {:.3f}, fastest runs {:.3f}, by CPU time "
      "{:.3f}\n",
      percent, share, part.route.best() / full.route.best(),
      1.0 / median_ratio(full.route, part.route, &Time::cpu));
  return {median_ratio(full.copy_same, full.route, &Time::wall), share};
}

}  // namespace

// Sort-last: one 1280x1024 display from four DEPTH layers, one a pipeserver (a 1280-wide DEPTH
// tile needs 4 + 2560 columns). Hybrid: 2x2 displays, each tile two DEPTH layers by two
// pipeservers.
void run_compositing(int repetitions, int cores, int coverage_percent) {
  const DepthScenario sort_last{
      "sort-last (4 DEPTH layers)", {{0, 1280, 1024, 0}}, 4, 4, 2564, 1024};
  const DepthScenario hybrid{
      "hybrid (2x2 displays, 2 DEPTH layers each)",
      {{0, 640, 512, 0}, {1, 640, 512, 0}, {2, 640, 512, 0}, {3, 640, 512, 0}},
      4,
      2,
      1284,
      1024};
  const DepthFigures a = run_depth(sort_last, coverage_percent, repetitions, cores);
  const DepthFigures b = run_depth(hybrid, coverage_percent, repetitions, cores);
  fmt::print("COMPOSITING/memcpy on {} cores (median of pairs): sort-last {:.2f}, hybrid {:.2f}\n",
             cores, a.full_over_memcpy, b.full_over_memcpy);
  fmt::print(
      "COMPOSITING at {}% coverage / full coverage on {} cores (median of pairs): sort-last "
      "{:.3f}, hybrid {:.3f}\n",
      coverage_percent, cores, a.part_over_full, b.part_over_full);
}

}  // namespace l2bench
