#include "lightning2_emu/router.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "composite.hpp"
#include "pixel_copy.hpp"
#include "router_detail.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2 {

using router_detail::Area;
using router_detail::BandState;
using router_detail::CoverageCounts;
using router_detail::CoverageScratch;
using router_detail::DisplayBands;
using router_detail::Target;

Router::Router(const Mesh& mesh, std::vector<DisplaySpec> displays, WorkerPool& pool,
               Rgb background)
    : mesh_(mesh), pool_(pool), background_(background), targets_(kMaxDisplays) {
  std::sort(displays.begin(), displays.end(),
            [](const DisplaySpec& a, const DisplaySpec& b) { return a.id < b.id; });
  // Bands are the tasks of write() and finish(). Many small ones keep both workers busy to the
  // end of a frame (a few large ones leave one worker idle while the other does the last band);
  // a band is still a few hundred strips, so taking one costs nothing in comparison.
  const int target_tasks = 32 * pool.workers();
  const int per_display =
      displays.empty() ? 1 : std::max(1, target_tasks / static_cast<int>(displays.size()));
  int band_offset = 0;
  for (const DisplaySpec& spec : displays) {
    mesh_.check_display(spec.id, spec.width, spec.height);
    Target& t = targets_[spec.id];
    if (t.index >= 0) throw MeshError(fmt::format("display {} given twice", spec.id));
    // Band heights are powers of two so the scan finds a strip's band with a shift.
    const int wanted = std::clamp(spec.height / 16, 1, per_display);
    while ((1 << t.band_shift) * wanted < spec.height) ++t.band_shift;
    t.index = static_cast<int>(displays_.size());
    t.width = spec.width;
    t.height = spec.height;
    t.band_offset = band_offset;
    displays_.emplace_back(spec, background);
    DisplayBands state;
    state.band_rows = 1 << t.band_shift;
    state.band_count = (spec.height + state.band_rows - 1) / state.band_rows;
    state.bands.resize(state.band_count);
    for (int b = 0; b < state.band_count; ++b) band_tasks_.push_back({t.index, b});
    band_offset += state.band_count;
    display_state_.push_back(std::move(state));
  }
  inputs_.resize(mesh_.input_count());
  for (int i = 0; i < mesh_.input_count(); ++i) inputs_[i].init(i, band_offset);
  band_stats_.reserve(band_tasks_.size());
  finish_tasks_.reserve(band_tasks_.size());
  scan_inputs_.reserve(inputs_.size());
  scratch_.resize(pool.workers());
}

Router::~Router() = default;

const InputFrameStats& Router::scanned(int input) const {
  return inputs_[input].stats();
}

bool Router::composites(int index) const {
  return !display_state_[index].plane.empty();
}

int Router::index_of_display(int id) const {
  return id >= 0 && id < kMaxDisplays ? targets_[id].index : -1;
}

void Router::scan(std::span<const InputFrame> frames) {
  if (static_cast<int>(frames.size()) > mesh_.input_count()) {
    throw MeshError(fmt::format("{} input frames given, the mesh ({}) has {} inputs", frames.size(),
                                mesh_.describe(), mesh_.input_count()));
  }
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const InputFrame& f = frames[i];
    if (!f.present()) continue;
    const std::string name = fmt::format("input {}", i);
    mesh_.check_input(static_cast<int>(i), f.width, f.height, name);
    if (f.bytes_per_pixel < 3 || f.bytes_per_pixel > 16 ||
        std::abs(f.stride) < static_cast<std::ptrdiff_t>(f.width) * f.bytes_per_pixel) {
      throw MeshError(
          fmt::format("{}: {} bytes per pixel with a stride of {} bytes cannot hold "
                      "{} pixels a row",
                      name, f.bytes_per_pixel, f.stride, f.width));
    }
  }
  scan_inputs_.clear();
  for (int i = 0; i < mesh_.input_count(); ++i) {
    const InputFrame f = i < static_cast<int>(frames.size()) ? frames[i] : InputFrame{};
    if (!f.present()) {
      inputs_[i].no_signal();
    } else if (!(predict_ && inputs_[i].predict(f))) {
      scan_inputs_.push_back(i);
    }
  }
  pool_.run(static_cast<int>(scan_inputs_.size()), [&](int task, int) {
    const int input = scan_inputs_[task];
    inputs_[input].parse(frames[input], targets_);
  });
  add_planes();
}

void Router::add_planes() {
  std::uint64_t wanted = 0;
  for (const router_detail::InputScan& in : inputs_) wanted |= in.composited();
  wanted &= ~planes_;
  for (int id = 0; wanted; ++id, wanted >>= 1) {
    if (!(wanted & 1) || targets_[id].index < 0) continue;
    const Target& t = targets_[id];
    DisplayBands& ds = display_state_[t.index];
    ds.plane.assign(static_cast<std::size_t>(t.width) * t.height, composite::kFar);
    planes_ |= std::uint64_t{1} << id;
    // Strips earlier write() calls of this frame wrote were COPY (the display had no plane):
    // opaque, the pixel of the highest input on top.
    for (const BandState& bs : ds.bands) {
      for (const Area& a : bs.areas) {
        for (int y = a.y0; y < a.y1; ++y) {
          std::uint32_t* rank = ds.plane.data() + static_cast<std::size_t>(y) * t.width;
          for (int x = a.x0; x < a.x1; ++x) {
            rank[x] = std::min(rank[x], composite::opaque_rank(a.input));
          }
        }
      }
    }
  }
}

void Router::finish(std::span<const int> display_indices, std::vector<DisplayFrameStats>& out) {
  finish_tasks_.clear();
  for (const int d : display_indices) {
    for (int b = 0; b < display_state_[d].band_count; ++b) finish_tasks_.push_back({d, b});
  }
  for (const int d : display_indices) choose_reached(d);
  band_stats_.resize(finish_tasks_.size());
  pool_.run(static_cast<int>(finish_tasks_.size()), [this](int task, int worker) {
    band_stats_[task] =
        finish_band(finish_tasks_[task].display, finish_tasks_[task].band, scratch_[worker]);
  });
  // Summed in a fixed order so the result never depends on which worker ran which band.
  out.clear();
  std::size_t task = 0;
  for (const int d : display_indices) {
    const DisplaySpec& spec = displays_[d].spec();
    DisplayFrameStats total{spec.id, spec.width, spec.height, 0, 0, 0};
    for (int b = 0; b < display_state_[d].band_count; ++b, ++task) {
      total.strips += band_stats_[task].strips;
      total.covered_pixels += band_stats_[task].covered_pixels;
      total.overdraw_pixels += band_stats_[task].overdraw_pixels;
    }
    display_state_[d].highest_input_written = -1;
    out.push_back(total);
  }
}

void Router::choose_reached(int display) {
  DisplayBands& ds = display_state_[display];
  if (ds.plane.empty()) return;
  const RgbImage& back = displays_[display].back();
  for (int k = 0; k < 2; ++k) {
    if (ds.reached[static_cast<std::size_t>(k)].buffer == back.data()) {
      ds.reached_now = k;
      return;
    }
  }
  // The slot that is not the front buffer's; everything may hold a pixel until finished once.
  ds.reached_now = ds.reached[0].buffer == displays_[display].front().data() ? 1 : 0;
  DisplayBands::Reached& r = ds.reached[static_cast<std::size_t>(ds.reached_now)];
  r.buffer = back.data();
  r.x0.assign(static_cast<std::size_t>(back.height()), 0);
  r.x1.assign(static_cast<std::size_t>(back.height()), back.width());
}

DisplayFrameStats Router::finish_band(int display, int band,
                                      router_detail::WorkerScratch& scratch) {
  DisplayBands& ds = display_state_[display];
  BandState& bs = ds.bands[band];
  RgbImage& back = displays_[display].back();
  const int y0 = band * ds.band_rows;
  const int y1 = std::min(back.height(), y0 + ds.band_rows);
  // A display with a plane fills the background only where its buffer may hold something else.
  DisplayBands::Reached* reached =
      ds.plane.empty() ? nullptr : &ds.reached[static_cast<std::size_t>(ds.reached_now)];
  const CoverageCounts counts = sweep_coverage(
      bs.areas, y0, y1, back.width(), scratch.coverage,
      [&](int from, int to, const std::vector<CoverageScratch::Gap>& gaps) {
        for (int y = from; y < to; ++y) {
          std::uint8_t* row = back.data() + y * back.stride();
          const int lo = reached ? reached->x0[static_cast<std::size_t>(y)] : 0;
          const int hi = reached ? reached->x1[static_cast<std::size_t>(y)] : back.width();
          for (const auto& g : gaps) {
            const int a = std::max(g.x0, lo), b = std::min(g.x1, hi);
            if (a < b) pixel_copy::fill_pixels(row + a * 3, b - a, background_);
          }
        }
      });
  DisplayFrameStats st;
  for (const Area& a : bs.areas) st.strips += a.y1 - a.y0;  // one area per run, a row per strip
  st.covered_pixels = counts.covered;
  if (!ds.plane.empty()) {  // strips inside which nothing was written show the background too
    // Only pixels inside an area can hold a rank: the rest got the background from the sweep
    // and keep kFar. So each row is settled from the first column an area reaches to the last
    // one: the cost follows what the strips cover (sparse DEPTH rows), not the display.
    std::vector<int>& x0 = scratch.row_x0;
    std::vector<int>& x1 = scratch.row_x1;
    x0.assign(static_cast<std::size_t>(y1 - y0), back.width());
    x1.assign(static_cast<std::size_t>(y1 - y0), 0);
    for (const Area& a : bs.areas) {
      for (int y = std::max<int>(a.y0, y0); y < std::min<int>(a.y1, y1); ++y) {
        x0[static_cast<std::size_t>(y - y0)] =
            std::min<int>(x0[static_cast<std::size_t>(y - y0)], a.x0);
        x1[static_cast<std::size_t>(y - y0)] =
            std::max<int>(x1[static_cast<std::size_t>(y - y0)], a.x1);
      }
    }
    st.covered_pixels = 0;
    for (int y = y0; y < y1; ++y) {
      const int from = x0[static_cast<std::size_t>(y - y0)],
                to = x1[static_cast<std::size_t>(y - y0)];
      reached->x0[static_cast<std::size_t>(y)] = from;
      reached->x1[static_cast<std::size_t>(y)] = to;
      if (from >= to) continue;
      st.covered_pixels += static_cast<std::uint64_t>(
          composite::settle(back.data() + y * back.stride() + from * 3,
                            ds.plane.data() + static_cast<std::size_t>(y) * back.width() + from,
                            to - from, background_.r, background_.g, background_.b));
    }
  }
  st.overdraw_pixels = counts.overdraw;
  bs.areas.clear();
  return st;
}

RouteReport Router::route(std::span<const InputFrame> frames) {
  scan(frames);
  const std::vector<std::uint8_t> all(inputs_.size(), 1);
  write(all);
  std::vector<int> every(displays_.size());
  for (std::size_t d = 0; d < every.size(); ++d) every[d] = static_cast<int>(d);
  RouteReport report;
  finish(every, report.displays);
  for (const router_detail::InputScan& in : inputs_) report.inputs.push_back(in.stats());
  return report;
}

}  // namespace l2
