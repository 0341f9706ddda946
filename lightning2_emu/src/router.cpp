#include "lightning2_emu/router.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "strip_headers/scanline_parser.hpp"

namespace l2 {
namespace {

// Strip pixels to a display row: a plain memcpy for RGB, dropping A for RGBA.
inline void copy_pixels(std::uint8_t* dst, const std::uint8_t* src, int pixels, int bpp) {
  if (bpp == 3) {
    std::memcpy(dst, src, static_cast<std::size_t>(pixels) * 3);
    return;
  }
  for (int i = 0; i < pixels; ++i, dst += 3, src += bpp) {
    dst[0] = src[0];
    dst[1] = src[1];
    dst[2] = src[2];
  }
}

constexpr std::size_t kPrefetchStrips = 4;
constexpr int kCacheLine = 64;

inline void prefetch_span(const std::uint8_t* p, int bytes) {
  for (int off = 0; off < bytes; off += kCacheLine) __builtin_prefetch(p + off, 0, 0);
}

inline void fill_pixels(std::uint8_t* dst, int pixels, Rgb c) {
  if (c.r == c.g && c.g == c.b) {
    std::memset(dst, c.r, static_cast<std::size_t>(pixels) * 3);
    return;
  }
  for (int i = 0; i < pixels; ++i, dst += 3) {
    dst[0] = c.r;
    dst[1] = c.g;
    dst[2] = c.b;
  }
}

}  // namespace

Router::Router(const Mesh& mesh, std::vector<DisplaySpec> displays, WorkerPool& pool,
               Rgb background)
    : mesh_(mesh), pool_(pool), background_(background), index_of_id_(kMaxDisplays, -1) {
  std::sort(displays.begin(), displays.end(),
            [](const DisplaySpec& a, const DisplaySpec& b) { return a.id < b.id; });
  // Enough bands that every worker has several to take, but no more: each band is a task.
  const int target_tasks = 4 * pool.workers();
  const int per_display =
      displays.empty() ? 1 : std::max(1, target_tasks / static_cast<int>(displays.size()));
  int band_offset = 0;
  for (const DisplaySpec& spec : displays) {
    mesh_.check_display(spec.id, spec.width, spec.height);
    if (index_of_id_[spec.id] >= 0) throw MeshError(fmt::format("display {} given twice", spec.id));
    index_of_id_[spec.id] = static_cast<int>(displays_.size());
    displays_.emplace_back(spec, background);
    DisplayState state;
    // Band heights are powers of two so the scan finds a strip's band with a shift.
    const int wanted = std::clamp(spec.height / 16, 1, per_display);
    state.band_shift = 0;
    while ((1 << state.band_shift) * wanted < spec.height) ++state.band_shift;
    state.band_rows = 1 << state.band_shift;
    state.band_count = (spec.height + state.band_rows - 1) / state.band_rows;
    state.band_offset = band_offset;
    state.bands.resize(state.band_count);
    for (int b = 0; b < state.band_count; ++b) {
      band_tasks_.push_back({static_cast<int>(display_state_.size()), b});
    }
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
}

int Router::index_of_display(int id) const {
  return id >= 0 && id < kMaxDisplays ? index_of_id_[id] : -1;
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
  InputFrameStats st;  // counted locally, stored once at the end
  st.input = input;
  st.present = true;
  const InputFrame& f = in.frame;
  // Headers sit where tiles start, and tiles span many scanlines: the headers of a scanline
  // predict those a few scanlines below. Fetching those early turns one memory latency per
  // header into overlapped requests.
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
      continue;
    }
    parse_scanline(f.row(y), f.width, f.bytes_per_pixel, st.errors, [&](const ParsedStrip& s) {
      if (headers < kTracked) header_x[headers++] = s.source_x - kHeaderPixels;
      const StripHeader& h = s.header;
      st.parities |= static_cast<std::uint8_t>(h.frame ? 2 : 1);
      if (h.op == StripOp::Skip) {
        ++st.skip_strips;
        return;
      }
      ++st.copy_strips;
      const int index = index_of_id_[h.display];
      if (index < 0) {
        ++st.errors.missing_display;
        return;
      }
      if (s.length == 0) return;  // a header in the last two pixels: nothing to route
      const DisplaySpec& d = displays_[index].spec();
      if (h.x >= d.width || h.y >= d.height) {
        ++st.errors.clips;
        return;
      }
      int length = s.length;
      if (h.x + length > d.width) {
        ++st.errors.clips;
        length = d.width - h.x;
      }
      const DisplayState& ds = display_state_[index];
      in.bands[ds.band_offset + (h.y >> ds.band_shift)].push_back(
          {s.source_x, y, h.x, h.y, static_cast<std::uint16_t>(length)});
      ++st.routed_strips;
      st.displays_fed |= std::uint64_t{1} << h.display;
    });
    if (y + kAhead < f.height) {
      const std::uint8_t* ahead = f.row(y + kAhead);
      __builtin_prefetch(ahead, 0, 0);
      for (int k = 0; k < headers; ++k) {
        __builtin_prefetch(ahead + header_x[k] * f.bytes_per_pixel, 0, 0);
      }
    }
  }
  in.stats = st;
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

void Router::group_by_row(BandState& band, int first_row, int rows) const {
  band.row_start.assign(rows + 1, 0);
  for (const Span& sp : band.spans) ++band.row_start[sp.row - first_row + 1];
  for (int r = 0; r < rows; ++r) band.row_start[r + 1] += band.row_start[r];
  band.by_row.resize(band.spans.size());
  // Placed from the back so each row keeps write order.
  for (std::size_t k = band.spans.size(); k-- > 0;) {
    const Span& sp = band.spans[k];
    band.by_row[--band.row_start[sp.row - first_row + 1]] = sp;
  }
  // row_start[r + 1] now holds the start of row r; shift it into place.
  for (int r = 0; r < rows; ++r) band.row_start[r] = band.row_start[r + 1];
  band.row_start[rows] = static_cast<std::uint32_t>(band.spans.size());
}

void Router::write_band(int display, int band, std::span<const std::uint8_t> route_input) {
  DisplayState& ds = display_state_[display];
  BandState& bs = ds.bands[band];
  RgbImage& back = displays_[display].back();
  std::uint8_t* const pixels = back.data();
  const std::size_t stride = back.stride();
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  const int first_row = band * ds.band_rows;
  // Only when an earlier write() this frame routed a higher input must strips go around what
  // it wrote (inputs delivering their frames at different refreshes). Those spans are grouped
  // by row once, here.
  const int earlier_highest = ds.highest_input_written;
  if (earlier_highest >= 0) {
    group_by_row(bs, first_row, std::min(ds.band_rows, back.height() - first_row));
  }
  // Inputs in ascending order and strips in scan order: the last write of a pixel is the one
  // spec §5 says wins.
  for (int i = 0; i < inputs; ++i) {
    if (!route_input[i]) continue;
    const InputState& in = inputs_[i];
    const int bpp = in.frame.bytes_per_pixel;
    const bool guard = earlier_highest > i;
    const std::vector<RoutedStrip>& strips = in.bands[ds.band_offset + band];
    const std::size_t count = strips.size();
    for (std::size_t k = 0; k < count; ++k) {
      const RoutedStrip& s = strips[k];
      // Strips jump from row to row, too irregular for the hardware prefetcher: ask for the
      // lines of a strip a few strips ahead, so its reads overlap this copy.
      if (k + kPrefetchStrips < count) {
        const RoutedStrip& a = strips[k + kPrefetchStrips];
        prefetch_span(in.frame.row(a.src_y) + a.src_x * bpp, a.length * bpp);
      }
      std::uint8_t* dst = pixels + s.dst_y * stride + s.dst_x * 3;
      const std::uint8_t* src = in.frame.row(s.src_y) + s.src_x * bpp;
      const int x1 = s.dst_x + s.length;
      if (!guard) {
        copy_pixels(dst, src, s.length, bpp);
      } else {
        copy_visible(dst, src, s.dst_x, x1, bpp, i, bs, s.dst_y - first_row);
      }
      bs.spans.push_back(
          {s.dst_y, s.dst_x, static_cast<std::uint16_t>(x1), static_cast<std::uint16_t>(i)});
    }
  }
}

void Router::copy_visible(std::uint8_t* dst, const std::uint8_t* src, int x0, int x1, int bpp,
                          int input, const BandState& band, int band_row) {
  // The strip minus every span a higher input wrote earlier: walk the row's spans for each
  // uncovered piece.
  const Span* first = band.by_row.data() + band.row_start[band_row];
  const Span* last = band.by_row.data() + band.row_start[band_row + 1];
  int cur = x0;
  while (cur < x1) {
    int next_block = x1, block_end = cur;
    for (const Span* sp = first; sp != last; ++sp) {
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
  pool_.run(static_cast<int>(finish_tasks_.size()), [this](int task, int) {
    band_stats_[task] = finish_band(finish_tasks_[task].display, finish_tasks_[task].band);
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

DisplayFrameStats Router::finish_band(int display, int band) {
  DisplayState& ds = display_state_[display];
  BandState& bs = ds.bands[band];
  RgbImage& back = displays_[display].back();
  const int width = back.width();
  const int y0 = band * ds.band_rows;
  const int y1 = std::min(back.height(), y0 + ds.band_rows);
  group_by_row(bs, y0, y1 - y0);
  DisplayFrameStats st;
  st.strips = bs.spans.size();
  const auto by_start = [](const Span& a, const Span& b) {
    return a.x0 < b.x0 || (a.x0 == b.x0 && a.x1 < b.x1);
  };
  for (int y = y0; y < y1; ++y) {
    Span* const first = bs.by_row.data() + bs.row_start[y - y0];
    Span* const last = bs.by_row.data() + bs.row_start[y - y0 + 1];
    std::uint8_t* row = back.data() + y * back.stride();
    if (!std::is_sorted(first, last, by_start)) std::sort(first, last, by_start);
    // Sweep by start column keeping the two furthest ends seen: a column is covered while the
    // furthest end lies beyond it and overdrawn while the second furthest does.
    int end1 = 0, end2 = 0, filled = 0;
    for (const Span* sp = first;; ++sp) {
      const int start = sp != last ? sp->x0 : width;
      if (start > filled) {
        const int gap_from = std::max(filled, end1);
        if (start > gap_from) fill_pixels(row + gap_from * 3, start - gap_from, background_);
        st.covered_pixels += std::max(0, std::min(end1, start) - filled);
        st.overdraw_pixels += std::max(0, std::min(end2, start) - filled);
        filled = start;
      }
      if (sp == last) break;
      if (sp->x1 > end1) {
        end2 = end1;
        end1 = sp->x1;
      } else if (sp->x1 > end2) {
        end2 = sp->x1;
      }
    }
  }
  bs.spans.clear();
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
