#include "tilelayout/sparse_depth.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "strip_headers/extension_word.hpp"

namespace l2 {
namespace {

// Four columns of header and extension word before each span's payload (spec §7).
constexpr int kSpanGap = kHeaderPixels + kExtensionPixels;
static_assert(kSparseMergeGap >= 3, "a gap of three pixels or more is what makes spans fit");

std::uint32_t rgb_at(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
}

bool skippable(const std::uint8_t* colour, const std::uint8_t* depth, const DepthSkip& s) {
  const std::uint32_t d = rgb_at(depth);
  if (d >= s.far_from) return true;
  return s.skip_background && d == s.background_depth && colour[0] == s.background[0] &&
         colour[1] == s.background[1] && colour[2] == s.background[2];
}

bool inside(const DisplayTile& a, const DisplayTile& b) {
  const Rect& r = a.on_display;
  const Rect& o = b.on_display;
  return a.display == b.display && r.x >= o.x && r.y >= o.y && r.x + r.w <= o.x + o.w &&
         r.y + r.h <= o.y + o.h;
}

bool overlap(const DisplayTile& a, const DisplayTile& b) {
  const Rect& r = a.on_display;
  const Rect& o = b.on_display;
  return a.display == b.display && r.x < o.x + o.w && o.x < r.x + r.w && r.y < o.y + o.h &&
         o.y < r.y + r.h;
}

// The DEPTH tiles of layer-0 pipeservers, each with its pipeserver.
std::vector<std::pair<const DisplayTile*, int>> layer_zero_tiles(const TileLayout& layout) {
  std::vector<std::pair<const DisplayTile*, int>> out;
  for (const PipeserverPlan& p : layout.pipeservers) {
    if (p.layer != 0) continue;
    for (const PackedTile& t : p.tiles) {
      if (t.tile.compositing == Compositing::Depth) out.push_back({&t.tile, p.pipeserver});
    }
  }
  return out;
}

bool layers_nest(const TileLayout& layout) {
  const auto zero = layer_zero_tiles(layout);
  for (std::size_t i = 0; i < zero.size(); ++i) {
    for (std::size_t j = i + 1; j < zero.size(); ++j) {
      if (overlap(*zero[i].first, *zero[j].first)) return false;
    }
  }
  for (const PipeserverPlan& p : layout.pipeservers) {
    if (p.layer == 0) continue;
    for (const PackedTile& t : p.tiles) {
      if (t.tile.compositing != Compositing::Depth) continue;
      const bool behind = std::any_of(zero.begin(), zero.end(), [&](const auto& z) {
        return z.second < p.pipeserver && inside(t.tile, *z.first);
      });
      if (!behind) return false;
    }
  }
  return true;
}

}  // namespace

DepthSkip depth_skip_of(const TileLayout& layout, int pipeserver,
                        std::array<std::uint8_t, 3> background) {
  DepthSkip skip;
  if (pipeserver < 0 || pipeserver >= static_cast<int>(layout.pipeservers.size()) ||
      !layers_nest(layout)) {
    return skip;
  }
  if (layout.pipeservers[static_cast<std::size_t>(pipeserver)].layer == 0) {
    skip.skip_background = true;
    skip.background = background;
  } else {
    skip.far_from = 0xFFFFFE;
  }
  return skip;
}

int sparse_columns(std::span<const DepthSpan> spans) {
  int columns = 0;
  for (const DepthSpan& s : spans) columns += kSpanGap + 2 * (s.x1 - s.x0);
  return columns;
}

void find_depth_spans(const std::uint8_t* colour, const std::uint8_t* depth, int w,
                      const DepthSkip& skip, std::vector<DepthSpan>& spans) {
  spans.clear();
  int x = 0;
  while (x < w) {
    while (x < w && skippable(colour + 3 * x, depth + 3 * x, skip)) ++x;
    if (x == w) break;
    const int start = x;
    while (x < w && !skippable(colour + 3 * x, depth + 3 * x, skip)) ++x;
    if (!spans.empty() && start - spans.back().x1 < kSparseMergeGap) {
      spans.back().x1 = x;
    } else {
      spans.push_back({start, x});
    }
  }
  // Spans kSparseMergeGap (>= 3) apart leave 2 (w - sent) - 4 (spans - 1) >= 0 columns, an even
  // number. Two are too few for a SKIP (header and one pixel): that is one span that misses one
  // pixel of the row (with two spans or more, w - sent >= 16 > 2 spans - 1), and it takes it.
  if (!spans.empty() && kSpanGap + 2 * w - sparse_columns(spans) == kHeaderPixels) {
    spans = {{0, w}};
  }
}

void pack_sparse_row(std::uint8_t* gap, const StripHeader& row, std::span<const DepthSpan> spans,
                     std::vector<std::uint8_t>& scratch) {
  const int w = row.width;
  // One span over the whole row is the dense row as drawn.
  if (spans.size() == 1 && spans[0].x0 == 0 && spans[0].x1 == w) return;
  const std::size_t pixel_bytes = 3 * static_cast<std::size_t>(w);
  std::uint8_t* const payload = gap + 3 * kSpanGap;
  scratch.assign(payload, payload + 2 * pixel_bytes);
  const std::uint8_t* colour = scratch.data();
  const std::uint8_t* depth = colour + pixel_bytes;
  const std::uint64_t word = encode(Extension::depth());
  std::uint8_t* out = gap;
  for (const DepthSpan& s : spans) {
    StripHeader h = row;
    h.x = static_cast<std::uint16_t>(row.x + s.x0);
    h.width = static_cast<std::uint16_t>(s.x1 - s.x0);
    write_header_pixels(encode(h), out, 3);
    write_header_pixels(word, out + 3 * kHeaderPixels, 3);
    const std::size_t bytes = 3 * static_cast<std::size_t>(h.width);
    out += 3 * kSpanGap;
    std::memcpy(out, colour + 3 * s.x0, bytes);
    std::memcpy(out + bytes, depth + 3 * s.x0, bytes);
    out += 2 * bytes;
  }
  const int left = kSpanGap + 2 * w - sparse_columns(spans);
  if (left <= 0) return;
  write_header_pixels(encode(StripHeader::skip(row.frame, left - kHeaderPixels)), out, 3);
  std::memset(out + 3 * kHeaderPixels, 0, 3 * static_cast<std::size_t>(left - kHeaderPixels));
}

}  // namespace l2
