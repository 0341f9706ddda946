#include "lightning2_emu/router.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "pixel_copy.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2 {
namespace {

using pixel_copy::copy_pixels;
using pixel_copy::fill_pixels;
using pixel_copy::prefetch_bytes;

// Strips of a run ahead whose source lines are asked for while one is copied.
constexpr int kPrefetchRows = 4;

// Where a strip goes, packed into one word so that "does it continue that run" is one compare:
// band list, then first column, row and length in 13 bits each (a row one past 4095 fits).
constexpr std::uint64_t run_key(int list, int x, int y, int length) {
  return std::uint64_t(list) << 39 | std::uint64_t(x) << 26 | std::uint64_t(y) << 13 |
         std::uint64_t(length);
}

}  // namespace

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
    DisplayState state;
    state.band_rows = 1 << t.band_shift;
    state.band_count = (spec.height + state.band_rows - 1) / state.band_rows;
    state.bands.resize(state.band_count);
    for (int b = 0; b < state.band_count; ++b) band_tasks_.push_back({t.index, b});
    band_offset += state.band_count;
    display_state_.push_back(std::move(state));
  }
  inputs_.resize(mesh_.input_count());
  for (int i = 0; i < mesh_.input_count(); ++i) {
    inputs_[i].stats.input = i;
    inputs_[i].bands.resize(band_offset);
  }
  band_stats_.reserve(band_tasks_.size());
  finish_tasks_.reserve(band_tasks_.size());
  scan_inputs_.reserve(inputs_.size());
  scratch_.resize(pool.workers());
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
    InputState& in = inputs_[i];
    in.frame = i < static_cast<int>(frames.size()) ? frames[i] : InputFrame{};
    if (in.frame.present()) {
      scan_inputs_.push_back(i);
    } else {
      in.stats = InputFrameStats{};
      in.stats.input = i;
      for (auto& band : in.bands) band.clear();
    }
  }
  pool_.run(static_cast<int>(scan_inputs_.size()),
            [this](int task, int) { scan_input(scan_inputs_[task]); });
}

void Router::scan_input(int input) {
  InputState& in = inputs_[input];
  for (auto& band : in.bands) band.clear();
  const InputFrame& f = in.frame;
  // Open runs by source column, of the last scanline and of this one. A strip takes at least
  // three pixels (header included), which bounds how many a scanline holds.
  const std::size_t most = static_cast<std::size_t>(f.width) / (kHeaderPixels + 1) + 1;
  if (in.open.size() < most) in.open.resize(most);
  if (in.opening.size() < most) in.opening.resize(most);
  OpenRun* open = in.open.data();
  OpenRun* opening = in.opening.data();
  std::size_t open_count = 0;
  // Counted in locals, stored once at the end.
  StripErrorCounts errors;
  std::uint64_t copies = 0, skips = 0, routed = 0, fed = 0;
  std::uint8_t parities = 0;
  // Headers sit where tiles start, and tiles span many scanlines: the headers of a scanline
  // predict those a few scanlines below. Fetching those early turns one memory latency per
  // header into overlapped requests. They are fetched into every cache level because write()
  // reads the same lines again: a strip starts right after its header.
  constexpr int kAhead = 4, kTracked = 32;
  int header_x[kTracked];
  for (int y = 0; y < f.height; ++y) {
    int headers = 0;
    // A black start is an END: most scanlines below the packed tiles are black.
    const std::uint8_t* first = f.row(y);
    if (f.width >= kHeaderPixels && (first[0] | first[1] | first[2]) == 0 &&
        (first[f.bytes_per_pixel] | first[f.bytes_per_pixel + 1] | first[f.bytes_per_pixel + 2]) ==
            0) {
      if (y + kAhead < f.height) __builtin_prefetch(f.row(y + kAhead), 0, 0);
      open_count = 0;
      continue;
    }
    std::size_t next_open = 0, opening_count = 0;
    const std::int64_t row_offset = std::int64_t{f.stride} * y;
    parse_scanline(f.row(y), f.width, f.bytes_per_pixel, errors, [&](const ParsedStrip& s) {
      if (headers < kTracked) header_x[headers++] = s.source_x - kHeaderPixels;
      const StripHeader& h = s.header;
      parities |= static_cast<std::uint8_t>(h.frame ? 2 : 1);
      if (h.op == StripOp::Skip) {
        ++skips;
        return;
      }
      ++copies;
      const Target& t = targets_[h.display];
      if (t.index < 0) {
        ++errors.missing_display;
        return;
      }
      if (s.length == 0) return;  // a header in the last two pixels: nothing to route
      if (h.x >= t.width || h.y >= t.height) {
        ++errors.clips;
        return;
      }
      int length = s.length;
      if (h.x + length > t.width) {
        ++errors.clips;
        length = t.width - h.x;
      }
      ++routed;
      fed |= std::uint64_t{1} << h.display;
      const int list = t.band_offset + (h.y >> t.band_shift);
      // Strips come left to right, as they did on the last scanline: walk its open runs along.
      // A strip continues the run open at its source column if it is that run's next row.
      const std::uint64_t key = run_key(list, h.x, h.y, length);
      while (next_open < open_count && open[next_open].src_x < s.source_x) ++next_open;
      if (next_open < open_count && open[next_open].src_x == s.source_x &&
          open[next_open].next_key == key) {
        OpenRun& o = opening[opening_count++];
        o = open[next_open];
        ++in.bands[list][o.run].rows;
        o.next_key += run_key(0, 0, 1, 0);
        return;
      }
      std::vector<Run>& runs = in.bands[list];
      opening[opening_count++] = {s.source_x, static_cast<std::uint32_t>(runs.size()),
                                  key + run_key(0, 0, 1, 0)};
      runs.push_back({row_offset + std::int64_t{s.source_x} * f.bytes_per_pixel, s.source_x,
                      y - h.y, h.x, h.y, static_cast<std::uint16_t>(length), 1});
    });
    std::swap(open, opening);
    open_count = opening_count;
    if (y + kAhead < f.height) {
      const std::uint8_t* ahead = f.row(y + kAhead);
      __builtin_prefetch(ahead, 0, 3);
      for (int k = 0; k < headers; ++k) {
        __builtin_prefetch(ahead + header_x[k] * f.bytes_per_pixel, 0, 3);
      }
    }
  }
  // Writing a band run by run keeps scan order on every display row if runs are ordered by
  // source row lag, then source column: two runs meet on a display row at source rows that
  // differ by their lags, the same on every row they share. Runs of packed tiles mostly come in
  // that order already.
  const auto before = [](const Run& a, const Run& b) {
    return a.row_lag < b.row_lag || (a.row_lag == b.row_lag && a.src_x < b.src_x);
  };
  for (auto& runs : in.bands) {
    if (!std::is_sorted(runs.begin(), runs.end(), before)) {
      std::sort(runs.begin(), runs.end(), before);
    }
  }
  InputFrameStats& st = in.stats;
  st = InputFrameStats{};
  st.input = input;
  st.present = true;
  st.copy_strips = copies;
  st.skip_strips = skips;
  st.routed_strips = routed;
  st.parities = parities;
  st.displays_fed = fed;
  st.errors = errors;
}

void Router::write(std::span<const std::uint8_t> route_input) {
  if (std::none_of(route_input.begin(), route_input.end(), [](std::uint8_t r) { return r; })) {
    return;
  }
  pool_.run(static_cast<int>(band_tasks_.size()), [&](int task, int) {
    write_band(band_tasks_[task].display, band_tasks_[task].band, route_input);
  });
  int highest = -1;
  for (std::size_t i = 0; i < route_input.size() && i < inputs_.size(); ++i) {
    if (route_input[i]) highest = static_cast<int>(i);
  }
  for (DisplayState& ds : display_state_) {
    ds.highest_input_written = std::max(ds.highest_input_written, highest);
  }
}

void Router::group_by_row(BandState& band, int first_row, int rows) {
  band.row_start.assign(rows + 1, 0);
  for (const Area& a : band.areas) {
    for (int y = a.y0; y < a.y1; ++y) ++band.row_start[y - first_row + 1];
  }
  for (int r = 0; r < rows; ++r) band.row_start[r + 1] += band.row_start[r];
  band.by_row.resize(band.row_start[rows]);
  for (const Area& a : band.areas) {
    for (int y = a.y0; y < a.y1; ++y)
      band.by_row[band.row_start[y - first_row]++] = {a.x0, a.x1, a.input};
  }
  // row_start[r] now holds the end of row r, which is the start of row r + 1.
  for (int r = rows; r > 0; --r) band.row_start[r] = band.row_start[r - 1];
  band.row_start[0] = 0;
}

void Router::write_band(int display, int band, std::span<const std::uint8_t> route_input) {
  DisplayState& ds = display_state_[display];
  BandState& bs = ds.bands[band];
  RgbImage& back = displays_[display].back();
  std::uint8_t* const pixels = back.data();
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(back.stride());
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  const int first_row = band * ds.band_rows;
  // Only when an earlier write() this frame routed a higher input must strips go around what
  // it wrote (inputs delivering their frames at different refreshes). Those areas are listed
  // row by row once, here.
  const int earlier_highest = ds.highest_input_written;
  if (earlier_highest >= 0) {
    group_by_row(bs, first_row, std::min(ds.band_rows, back.height() - first_row));
  }
  // Inputs in ascending order and each input's runs in the order scan_input() left them: the
  // last write of a pixel is the one spec §5 says wins.
  const int band_list = targets_[displays_[display].id()].band_offset + band;
  for (int i = 0; i < inputs; ++i) {
    if (!route_input[i]) continue;
    const InputState& in = inputs_[i];
    const int bpp = in.frame.bytes_per_pixel;
    const std::ptrdiff_t src_stride = in.frame.stride;
    const bool guard = earlier_highest > i;
    for (const Run& r : in.bands[band_list]) {
      const std::uint8_t* src = in.frame.data + r.src;
      std::uint8_t* dst = pixels + r.dst_y * stride + r.dst_x * 3;
      const int bytes = r.length * bpp;
      // A run's strips are a constant stride apart in both frames, but the hardware prefetcher
      // does not follow a stride of whole scanlines: ask for the strips a few rows ahead.
      for (int k = 0; k < std::min<int>(kPrefetchRows, r.rows); ++k) {
        prefetch_bytes(src + k * src_stride, bytes);
      }
      for (int k = 0; k < r.rows; ++k, src += src_stride, dst += stride) {
        if (k + kPrefetchRows < r.rows) prefetch_bytes(src + kPrefetchRows * src_stride, bytes);
        if (!guard) {
          copy_pixels(dst, src, r.length, bpp);
        } else {
          copy_visible(dst, src, r.dst_x, r.dst_x + r.length, bpp, i, bs, r.dst_y + k - first_row);
        }
      }
      bs.areas.push_back({r.dst_y, static_cast<std::uint16_t>(r.dst_y + r.rows), r.dst_x,
                          static_cast<std::uint16_t>(r.dst_x + r.length),
                          static_cast<std::uint16_t>(i)});
      bs.strips += r.rows;
    }
  }
  pixel_copy::finish_streaming();
}

void Router::copy_visible(std::uint8_t* dst, const std::uint8_t* src, int x0, int x1, int bpp,
                          int input, const BandState& band, int band_row) {
  // The strip minus every span a higher input wrote earlier: walk the row's spans for each
  // uncovered piece.
  const BandState::Written* first = band.by_row.data() + band.row_start[band_row];
  const BandState::Written* last = band.by_row.data() + band.row_start[band_row + 1];
  int cur = x0;
  while (cur < x1) {
    int next_block = x1, block_end = cur;
    for (const BandState::Written* sp = first; sp != last; ++sp) {
      if (sp->input <= input || sp->x1 <= cur || sp->x0 >= x1) continue;
      if (sp->x0 <= cur) {
        block_end = std::max<int>(block_end, sp->x1);
      } else {
        next_block = std::min<int>(next_block, sp->x0);
      }
    }
    if (block_end > cur) {
      cur = block_end;
      continue;
    }
    copy_pixels(dst + (cur - x0) * 3, src + (cur - x0) * bpp, next_block - cur, bpp);
    cur = next_block;
  }
}

void Router::finish(std::span<const int> display_indices, std::vector<DisplayFrameStats>& out) {
  finish_tasks_.clear();
  for (const int d : display_indices) {
    for (int b = 0; b < display_state_[d].band_count; ++b) finish_tasks_.push_back({d, b});
  }
  band_stats_.resize(finish_tasks_.size());
  pool_.run(static_cast<int>(finish_tasks_.size()), [this](int task, int worker) {
    band_stats_[task] = finish_band(finish_tasks_[task].display, finish_tasks_[task].band,
                                    scratch_[worker].coverage);
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

DisplayFrameStats Router::finish_band(int display, int band, CoverageScratch& scratch) {
  DisplayState& ds = display_state_[display];
  BandState& bs = ds.bands[band];
  RgbImage& back = displays_[display].back();
  const int y0 = band * ds.band_rows;
  const int y1 = std::min(back.height(), y0 + ds.band_rows);
  const CoverageCounts counts =
      sweep_coverage(bs.areas, y0, y1, back.width(), scratch,
                     [&](int from, int to, const std::vector<CoverageScratch::Gap>& gaps) {
                       for (int y = from; y < to; ++y) {
                         std::uint8_t* row = back.data() + y * back.stride();
                         for (const auto& g : gaps)
                           fill_pixels(row + g.x0 * 3, g.x1 - g.x0, background_);
                       }
                     });
  DisplayFrameStats st;
  st.strips = bs.strips;
  st.covered_pixels = counts.covered;
  st.overdraw_pixels = counts.overdraw;
  bs.areas.clear();
  bs.strips = 0;
  return st;
}

RouteReport Router::route(std::span<const InputFrame> frames) {
  scan(frames);
  std::vector<std::uint8_t> all(inputs_.size(), 1);
  write(all);
  std::vector<int> every(displays_.size());
  for (std::size_t d = 0; d < every.size(); ++d) every[d] = static_cast<int>(d);
  RouteReport report;
  finish(every, report.displays);
  for (const InputState& in : inputs_) report.inputs.push_back(in.stats);
  return report;
}

}  // namespace l2
