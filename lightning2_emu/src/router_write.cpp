// Router::write(): the runs of the chosen inputs copied into the display back buffers, in
// parallel over display row bands. In a band the inputs go in ascending order and an input's runs
// in scan order (input_scan.cpp orders them), so that the last write of a pixel is the one spec
// §5 says wins.
//
// Copying runs band by band reads the input frames a few cache lines per scanline. Copying in
// source order instead (whole scanlines, each strip to its display) was tried: it reads better
// but scatters the writes over every tile of a scanline, and measured about 1.5x slower.
#include <algorithm>
#include <stdexcept>

#include "composite.hpp"
#include "lightning2_emu/router.hpp"
#include "pixel_copy.hpp"
#include "router_detail.hpp"

namespace l2 {

using router_detail::Area;
using router_detail::BandState;
using router_detail::DisplayBands;
using router_detail::InputScan;
using router_detail::Run;

namespace {

using pixel_copy::copy_pixels;
using pixel_copy::prefetch_bytes;

// Strips of a run ahead whose source lines are asked for while one is copied.
constexpr int kPrefetchRows = 4;

// A band's areas (written by earlier calls), row by row, for copy_visible().
void group_by_row(BandState& band, int first_row, int rows) {
  band.row_start.assign(rows + 1, 0);
  for (const Area& a : band.areas) {
    for (int y = a.y0; y < a.y1; ++y) ++band.row_start[y - first_row + 1];
  }
  for (int r = 0; r < rows; ++r) band.row_start[r + 1] += band.row_start[r];
  band.by_row.resize(band.row_start[rows]);
  for (const Area& a : band.areas) {
    for (int y = a.y0; y < a.y1; ++y) {
      band.by_row[band.row_start[y - first_row]++] = {a.x0, a.x1, a.input};
    }
  }
  // row_start[r] now holds the end of row r, which is the start of row r + 1.
  for (int r = rows; r > 0; --r) band.row_start[r] = band.row_start[r - 1];
  band.row_start[0] = 0;
}

// A strip minus every span a higher input wrote in an earlier call: walk the row's spans for
// each uncovered piece.
void copy_visible(std::uint8_t* dst, const std::uint8_t* src, int x0, int x1, int bpp, int input,
                  const BandState& band, int band_row) {
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

// The strips of a run, each by copy_row(dst, src, k), the source lines of each asked for a few
// rows ahead: a run's strips are a constant stride apart in both frames, but the hardware
// prefetcher does not follow a stride of whole scanlines. With kCheck the run belongs to a
// predicted frame: each strip's header, which sits in the line before or the line of the
// strip's first pixel and is read with it, is compared with the one predicted for it; false
// when one differs.
template <bool kCheck, class CopyRow>
bool copy_run(const Run& r, const std::uint8_t* src, std::ptrdiff_t src_stride, std::uint8_t* dst,
              std::ptrdiff_t stride, int bpp, std::uint64_t frame_bit, CopyRow&& copy_row) {
  const int head = kCheck ? kHeaderPixels * bpp : 0;  // the header's bytes, read with the strip
  const int bytes = r.length * bpp + head;
  for (int k = 0; k < std::min<int>(kPrefetchRows, r.rows); ++k) {
    prefetch_bytes(src - head + k * src_stride, bytes);
  }
  const router_detail::RunHeaders headers(r.message | frame_bit);
  bool held = true;
  for (int k = 0; k < r.rows; ++k, src += src_stride, dst += stride) {
    if (k + kPrefetchRows < r.rows) prefetch_bytes(src - head + kPrefetchRows * src_stride, bytes);
    if constexpr (kCheck) held &= router_detail::header_before(src, bpp) == headers.strip(k);
    copy_row(dst, src, k);
  }
  return held;
}

}  // namespace

void Router::write(const RouteChoice& choose) {
  if (write_checked(choose())) return;
  // A predicted frame was not what it was taken for: its input is parsed now, so its counts
  // may choose otherwise, and nothing predicted is left to miss.
  if (!write_checked(choose())) throw std::logic_error("router: a parsed frame missed");
}

void Router::write(std::span<const std::uint8_t> route_input) {
  write([route_input] { return route_input; });
}

bool Router::write_checked(std::span<const std::uint8_t> route_input) {
  int highest = -1;
  for (std::size_t i = 0; i < route_input.size() && i < inputs_.size(); ++i) {
    if (route_input[i]) highest = static_cast<int>(i);
  }
  for (DisplayBands& ds : display_state_) {
    for (BandState& bs : ds.bands) bs.earlier_areas = bs.areas.size();
  }
  // Predicted frames are checked while they are copied where their strips overlap nothing an
  // earlier call wrote this frame: a wrong one is then undone by forgetting what this call
  // wrote (the pixels of no recorded area get the background in finish(); the other inputs'
  // strips are written again, the same). Otherwise a wrong one might overwrite an earlier
  // call's strips, so the checks come first.
  // Compositing leaves ranks (composite.hpp) that forgetting areas does not undo: predictions
  // that write to a display with a plane are checked first too.
  bool onto_planes = false;
  for (std::size_t i = 0; i < route_input.size() && i < inputs_.size(); ++i) {
    onto_planes |= route_input[i] && inputs_[i].predicted() &&
                   (inputs_[i].stats().displays_fed & planes_) != 0;
  }
  const bool check_in_copy = !onto_planes && predictions_clear_of_earlier(route_input);
  if (!check_in_copy && !confirm_predictions(route_input, false)) return false;
  if (highest >= 0) {
    pool_.run(static_cast<int>(band_tasks_.size()),
              [&](int task, int) { write_band(task, route_input); });
  }
  if (check_in_copy && !confirm_predictions(route_input, true)) {
    for (DisplayBands& ds : display_state_) {
      for (BandState& bs : ds.bands) bs.areas.resize(bs.earlier_areas);
    }
    return false;
  }
  for (DisplayBands& ds : display_state_) {
    ds.highest_input_written = std::max(ds.highest_input_written, highest);
  }
  return true;
}

void Router::write_band(int task, std::span<const std::uint8_t> route_input) {
  const BandTask& t = band_tasks_[task];
  DisplayBands& ds = display_state_[t.display];
  if (!ds.plane.empty()) return composite_band(task, route_input);
  BandState& bs = ds.bands[t.band];
  RgbImage& back = displays_[t.display].back();
  std::uint8_t* const pixels = back.data();
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(back.stride());
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  const int first_row = t.band * ds.band_rows;
  // Only when an earlier write() this frame routed a higher input must strips go around what
  // it wrote (inputs delivering their frames at different refreshes). Those areas are listed
  // row by row once, here.
  const int earlier_highest = ds.highest_input_written;
  if (earlier_highest >= 0) {
    group_by_row(bs, first_row, std::min(ds.band_rows, back.height() - first_row));
  }
  for (int i = 0; i < inputs; ++i) {
    if (!route_input[i]) continue;
    const InputScan& in = inputs_[i];
    const InputFrame& frame = in.frame();
    const int bpp = frame.bytes_per_pixel;
    const std::ptrdiff_t src_stride = frame.stride;
    const bool guard = earlier_highest > i;
    const bool predicted = in.predicted();
    const std::uint64_t frame_bit = in.frame_bit();
    for (const Run& r : in.runs(task)) {
      const std::uint8_t* src = frame.data + r.src;
      std::uint8_t* dst = pixels + r.dst_y * stride + r.dst_x * 3;
      const auto whole = [&](std::uint8_t* d, const std::uint8_t* s, int) {
        copy_pixels(d, s, r.length, bpp);
      };
      if (predicted) {  // overlaps no earlier area (write()): no guard needed
        if (!copy_run<true>(r, src, src_stride, dst, stride, bpp, frame_bit, whole) &&
            (bs.mispredicted.empty() || bs.mispredicted.back() != i)) {
          bs.mispredicted.push_back(i);
        }
      } else if (!guard) {
        copy_run<false>(r, src, src_stride, dst, stride, bpp, 0, whole);
      } else {
        copy_run<false>(r, src, src_stride, dst, stride, bpp, 0,
                        [&](std::uint8_t* d, const std::uint8_t* s, int k) {
                          copy_visible(d, s, r.dst_x, r.dst_x + r.length, bpp, i, bs,
                                       r.dst_y + k - first_row);
                        });
      }
      bs.areas.push_back({r.dst_y, static_cast<std::uint16_t>(r.dst_y + r.rows), r.dst_x,
                          static_cast<std::uint16_t>(r.dst_x + r.length),
                          static_cast<std::uint16_t>(i)});
    }
  }
  pixel_copy::finish_streaming();
}

// A band of a display with a compositing plane: every strip pixel by the rules of
// composite.hpp, which give the bus-order result whatever order the inputs come in, so no strip
// goes around another. Predicted inputs were checked before (write_checked()).
void Router::composite_band(int task, std::span<const std::uint8_t> route_input) {
  const BandTask& t = band_tasks_[task];
  DisplayBands& ds = display_state_[t.display];
  BandState& bs = ds.bands[t.band];
  RgbImage& back = displays_[t.display].back();
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(back.stride());
  const int inputs = static_cast<int>(std::min(route_input.size(), inputs_.size()));
  for (int i = 0; i < inputs; ++i) {
    if (!route_input[i]) continue;
    const InputFrame& frame = inputs_[i].frame();
    const int bpp = frame.bytes_per_pixel;
    for (const Run& r : inputs_[i].runs(task)) {
      const std::uint8_t* src = frame.data + r.src;
      std::uint8_t* dst = back.data() + r.dst_y * stride + r.dst_x * 3;
      std::uint32_t* rank =
          ds.plane.data() + static_cast<std::size_t>(r.dst_y) * back.width() + r.dst_x;
      // A strip's colour pixels, and for DEPTH its depth pixels depth_at pixels on.
      const int read_bytes =
          (r.kind == router_detail::StripKind::Depth ? r.depth_at + r.length : r.length) * bpp;
      const auto each_row = [&](auto&& apply) {
        for (int k = 0; k < r.rows; ++k, src += frame.stride, dst += stride, rank += back.width()) {
          if (k + kPrefetchRows < r.rows) {
            prefetch_bytes(src + kPrefetchRows * frame.stride, read_bytes);
          }
          apply();
        }
      };
      const int n = r.length;
      switch (r.kind) {
        case router_detail::StripKind::Copy:
        case router_detail::StripKind::Key: {
          const bool keyed = r.kind == router_detail::StripKind::Key;
          each_row([&] { composite::overlay(keyed, dst, rank, src, n, bpp, r.key, i); });
          break;
        }
        case router_detail::StripKind::Depth:
          each_row([&] {
            const std::uint8_t* depth = src + std::ptrdiff_t{r.depth_at} * bpp;
            composite::depth(dst, rank, src, depth, n, bpp, i);
          });
          break;
      }
      bs.areas.push_back({r.dst_y, static_cast<std::uint16_t>(r.dst_y + r.rows), r.dst_x,
                          static_cast<std::uint16_t>(r.dst_x + r.length),
                          static_cast<std::uint16_t>(i)});
    }
  }
}

}  // namespace l2
