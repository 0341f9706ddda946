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
    state.band_count = std::clamp(spec.height / 16, 1, per_display);
    state.band_rows = (spec.height + state.band_count - 1) / state.band_count;
    state.band_count = (spec.height + state.band_rows - 1) / state.band_rows;
    state.band_offset = band_offset;
    state.rows.resize(spec.height);
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
  InputFrameStats& st = in.stats;
  st = InputFrameStats{};
  st.input = input;
  st.present = true;
  const InputFrame& f = in.frame;
  for (int y = 0; y < f.height; ++y) {
    parse_scanline(f.row(y), f.width, f.bytes_per_pixel, st.errors, [&](const ParsedStrip& s) {
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
      in.bands[ds.band_offset + h.y / ds.band_rows].push_back(
          {s.source_x, y, h.x, h.y, static_cast<std::uint16_t>(length)});
      ++st.routed_strips;
      st.displays_fed |= std::uint64_t{1} << h.display;
    });
  }
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

void Router::write_band(int display, int band, std::span<const std::uint8_t> route_input) {
  DisplayState& ds = display_state_[display];
  RgbImage& back = displays_[display].back();
  std::uint8_t* const pixels = back.data();
  const std::size_t stride = back.stride();
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  // Inputs in ascending order and strips in scan order: the last write of a pixel is the one
  // spec §5 says wins.
  for (int i = 0; i < inputs; ++i) {
    if (!route_input[i]) continue;
    const InputState& in = inputs_[i];
    const int bpp = in.frame.bytes_per_pixel;
    // Only when an earlier write() this frame routed a higher input must the strips of this
    // one go around what it wrote (inputs delivering their frames at different refreshes).
    const bool guard = ds.highest_input_written > i;
    for (const RoutedStrip& s : in.bands[ds.band_offset + band]) {
      std::uint8_t* dst = pixels + s.dst_y * stride + s.dst_x * 3;
      const std::uint8_t* src = in.frame.row(s.src_y) + s.src_x * bpp;
      std::vector<Span>& spans = ds.rows[s.dst_y];
      const int x1 = s.dst_x + s.length;
      if (!guard) {
        copy_pixels(dst, src, s.length, bpp);
      } else {
        // Visible parts: the strip minus every span a higher input wrote. Spans of one row
        // are few; walk them for each uncovered piece.
        int cur = s.dst_x;
        while (cur < x1) {
          int next_block = x1, block_end = cur;
          for (const Span& sp : spans) {
            if (sp.input <= i || sp.x1 <= cur || sp.x0 >= x1) continue;
            if (sp.x0 <= cur) {
              block_end = std::max<int>(block_end, sp.x1);
            } else {
              next_block = std::min<int>(next_block, sp.x0);
            }
          }
          if (block_end > cur) {
            cur = block_end;
            continue;
          }
          copy_pixels(dst + (cur - s.dst_x) * 3, src + (cur - s.dst_x) * bpp, next_block - cur,
                      bpp);
          cur = next_block;
        }
      }
      spans.push_back({s.dst_x, static_cast<std::uint16_t>(x1), static_cast<std::uint16_t>(i)});
    }
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
  RgbImage& back = displays_[display].back();
  const int width = back.width();
  const int y0 = band * ds.band_rows;
  const int y1 = std::min(back.height(), y0 + ds.band_rows);
  DisplayFrameStats st;
  for (int y = y0; y < y1; ++y) {
    std::vector<Span>& spans = ds.rows[y];
    std::uint8_t* row = back.data() + y * back.stride();
    st.strips += spans.size();
    if (!std::is_sorted(spans.begin(), spans.end(),
                        [](const Span& a, const Span& b) { return a.x0 < b.x0; })) {
      std::sort(spans.begin(), spans.end(),
                [](const Span& a, const Span& b) { return a.x0 < b.x0; });
    }
    // Sweep by start column keeping the two furthest ends seen: a column is covered while the
    // furthest end lies beyond it and overdrawn while the second furthest does.
    int end1 = 0, end2 = 0, filled = 0;
    for (std::size_t k = 0; k <= spans.size(); ++k) {
      const int start = k < spans.size() ? spans[k].x0 : width;
      if (start > filled) {
        const int gap_from = std::max(filled, end1);
        if (start > gap_from) fill_pixels(row + gap_from * 3, start - gap_from, background_);
        st.covered_pixels += std::max(0, std::min(end1, start) - filled);
        st.overdraw_pixels += std::max(0, std::min(end2, start) - filled);
        filled = start;
      }
      if (k == spans.size()) break;
      const int end = spans[k].x1;
      if (end > end1) {
        end2 = end1;
        end1 = end;
      } else if (end > end2) {
        end2 = end;
      }
    }
    spans.clear();
  }
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
