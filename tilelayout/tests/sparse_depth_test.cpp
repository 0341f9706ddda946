// Sparse DEPTH rows: which spans a row sends, and the scanline they make, read back with the
// spec's parser. Expected spans and columns are worked out by hand from the rules.
#include "tilelayout/sparse_depth.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "strip_headers/scanline_parser.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr std::uint32_t kFar = 0xFFFFFF;

// A dense DEPTH row of w pixels: colour pixel i is (i, 100, 200), depth the given value.
struct Row {
  std::vector<std::uint8_t> colour, depth;
  explicit Row(const std::vector<std::uint32_t>& depths) {
    for (std::size_t i = 0; i < depths.size(); ++i) {
      colour.insert(colour.end(), {static_cast<std::uint8_t>(i), 100, 200});
      const std::uint32_t d = depths[i];
      depth.insert(depth.end(), {static_cast<std::uint8_t>(d >> 16),
                                 static_cast<std::uint8_t>(d >> 8), static_cast<std::uint8_t>(d)});
    }
  }
  int w() const { return static_cast<int>(depth.size() / 3); }
  std::vector<DepthSpan> spans(const DepthSkip& skip = {}) const {
    std::vector<DepthSpan> out{{99, 99}};  // cleared first
    find_depth_spans(colour.data(), depth.data(), w(), skip, out);
    return out;
  }
};

// w pixels at the far plane but for [from, to) at depth 5.
std::vector<std::uint32_t> drawn(int w, std::initializer_list<std::array<int, 2>> ranges) {
  std::vector<std::uint32_t> d(static_cast<std::size_t>(w), kFar);
  for (const auto& r : ranges) {
    for (int x = r[0]; x < r[1]; ++x) d[static_cast<std::size_t>(x)] = 5;
  }
  return d;
}

TEST(SparseDepthSpans, AllFarSendsNothing) {
  EXPECT_TRUE(Row(drawn(40, {})).spans().empty());
}

TEST(SparseDepthSpans, AllDrawnIsOneSpan) {
  EXPECT_EQ(Row(drawn(40, {{0, 40}})).spans(), (std::vector<DepthSpan>{{0, 40}}));
}

TEST(SparseDepthSpans, SpansFarApartStaySeparate) {
  // 10..20 and 50..60 of 100: a gap of 30 pixels.
  EXPECT_EQ(Row(drawn(100, {{10, 20}, {50, 60}})).spans(),
            (std::vector<DepthSpan>{{10, 20}, {50, 60}}));
}

TEST(SparseDepthSpans, ShortGapsAreSentWithTheirSpans) {
  // A gap of 15 (< kSparseMergeGap) is taken in; one of 16 is not.
  EXPECT_EQ(Row(drawn(100, {{10, 20}, {35, 40}})).spans(), (std::vector<DepthSpan>{{10, 40}}));
  EXPECT_EQ(Row(drawn(100, {{10, 20}, {36, 40}})).spans(),
            (std::vector<DepthSpan>{{10, 20}, {36, 40}}));
}

TEST(SparseDepthSpans, TwoColumnsLeftWidenTheSpanToTheRow) {
  // w = 10, drawn 0..9: one span of 9 takes 4 + 18 = 22 of 24 columns; two are too few for a
  // SKIP, so the span takes pixel 9 as well.
  EXPECT_EQ(Row(drawn(10, {{0, 9}})).spans(), (std::vector<DepthSpan>{{0, 10}}));
  // Drawn 1..10: no pixel after it, so the span takes pixel 0.
  EXPECT_EQ(Row(drawn(10, {{1, 10}})).spans(), (std::vector<DepthSpan>{{0, 10}}));
  // Two spans never leave two columns: 2 (w - sent) - 4 = 2 needs a gap of 3.
  EXPECT_EQ(Row(drawn(20, {{0, 1}, {17, 20}})).spans(), (std::vector<DepthSpan>{{0, 1}, {17, 20}}));
}

TEST(SparseDepthSpans, LayerZeroLeavesOutItsClearWhereItIsTheBackground) {
  // Layer 0 sends its clear one step nearer (FFFFFE): left out where its colour is the
  // background, kept where it is not.
  std::vector<std::uint32_t> d(40, 0xFFFFFE);
  for (int x = 20; x < 30; ++x) d[static_cast<std::size_t>(x)] = 7;
  Row row(d);
  DepthSkip skip;
  skip.skip_background = true;
  skip.background = {1, 100, 200};  // pixel 1's colour alone
  // Everything but pixel 1 and 20..29 is kept: 0..20 (pixel 1 inside) and 30..40 merge.
  EXPECT_EQ(row.spans(skip), (std::vector<DepthSpan>{{0, 40}}));
  for (int x = 0; x < 40; ++x) {  // now every clear pixel has the background's colour
    if (x < 20 || x >= 30) {
      row.colour[3 * static_cast<std::size_t>(x)] = 1;
    }
  }
  EXPECT_EQ(row.spans(skip), (std::vector<DepthSpan>{{20, 30}}));
  // Without skip_background the clear is sent: it writes.
  EXPECT_EQ(row.spans(), (std::vector<DepthSpan>{{0, 40}}));
  // Behind layer 0, FFFFFE is left out like the far plane.
  DepthSkip behind;
  behind.far_from = 0xFFFFFE;
  EXPECT_EQ(row.spans(behind), (std::vector<DepthSpan>{{20, 30}}));
}

TEST(SparseDepthSkip, NestedLayersLeaveOutMoreThanTheFarPlane) {
  // walls/hybrid-2x1.toml: layer 0 is pipeservers 0 and 1, layer 1 pipeservers 2 and 3 over the
  // same tiles, pipeserver 4 the overlay (KEY).
  TileLayout layout = plan_layout(load_wall(std::string(L2_WALLS_DIR) + "/hybrid-2x1.toml"));
  const std::array<std::uint8_t, 3> black{};
  for (int s : {0, 1}) {
    const DepthSkip k = depth_skip_of(layout, s, black);
    EXPECT_TRUE(k.skip_background) << s;
    EXPECT_EQ(k.far_from, 0xFFFFFFu) << s;
  }
  for (int s : {2, 3}) {
    const DepthSkip k = depth_skip_of(layout, s, black);
    EXPECT_FALSE(k.skip_background) << s;
    EXPECT_EQ(k.far_from, 0xFFFFFEu) << s;
  }
  // A layer-1 tile moved one column past every layer-0 tile: nothing is known to lie in front
  // of it, so every pipeserver leaves out the far plane only.
  PipeserverPlan& behind = layout.pipeservers[2];
  ASSERT_EQ(behind.layer, 1);
  ASSERT_EQ(behind.tiles.front().tile.compositing, Compositing::Depth);
  behind.tiles.front().tile.on_display.x += 1;
  for (int s : {0, 1, 2, 3, 4}) {
    const DepthSkip k = depth_skip_of(layout, s, black);
    EXPECT_FALSE(k.skip_background) << s;
    EXPECT_EQ(k.far_from, 0xFFFFFFu) << s;
  }
}

// The scanline of one DEPTH tile of width w at column 0 (EXT header, word, colour, depth)
// followed by an END, packed sparse, and what the parser finds in it.
struct Packed {
  std::vector<std::uint8_t> line;
  std::vector<ParsedStrip> strips;
  StripErrorCounts errors;
};
Packed pack(const Row& row, const std::vector<DepthSpan>& spans) {
  const int w = row.w();
  const int width_px = 4 + 2 * w + 2;
  Packed p;
  p.line.assign(static_cast<std::size_t>(width_px) * 3, 0xAB);
  StripHeader h = StripHeader::copy(true, 3, 100, 7, w);
  h.op = StripOp::Ext;
  write_header_pixels(encode(h), p.line.data(), 3);
  write_header_pixels(encode(Extension::depth()), p.line.data() + 6, 3);
  std::copy(row.colour.begin(), row.colour.end(), p.line.begin() + 12);
  std::copy(row.depth.begin(), row.depth.end(), p.line.begin() + 12 + 3 * w);
  write_header_pixels(encode(StripHeader::end()), p.line.data() + 3 * (4 + 2 * w), 3);
  std::vector<std::uint8_t> scratch;
  pack_sparse_row(p.line.data(), h, spans, scratch);
  parse_scanline(p.line.data(), width_px, 3, p.errors,
                 [&](const ParsedStrip& s) { p.strips.push_back(s); });
  return p;
}

TEST(SparseDepthRow, SpansBecomeDepthStripsAndTheRestOneSkip) {
  const Row row(drawn(100, {{10, 20}, {50, 60}}));
  const Packed p = pack(row, row.spans());
  EXPECT_EQ(p.errors.total(), 0u);
  ASSERT_EQ(p.strips.size(), 3u);
  // Span 10..20 at column 0: header, word, colour at 4..13, depth at 14..23.
  EXPECT_TRUE(p.strips[0].is(ExtKind::Depth));
  EXPECT_EQ(p.strips[0].header.display, 3);
  EXPECT_EQ(p.strips[0].header.x, 110);
  EXPECT_EQ(p.strips[0].header.y, 7);
  EXPECT_EQ(p.strips[0].header.width, 10);
  EXPECT_TRUE(p.strips[0].header.frame);
  EXPECT_EQ(p.strips[0].source_x, 4);
  // Span 50..60 at column 24.
  EXPECT_TRUE(p.strips[1].is(ExtKind::Depth));
  EXPECT_EQ(p.strips[1].header.x, 150);
  EXPECT_EQ(p.strips[1].source_x, 28);
  // A SKIP from column 48 over the rest of the 204 columns: 204 - 48 - 2 = 154 pixels, so the
  // END lands at 204 as in the dense row.
  EXPECT_EQ(p.strips[2].header.op, StripOp::Skip);
  EXPECT_TRUE(p.strips[2].header.frame);
  EXPECT_EQ(p.strips[2].header.width, 154);
  EXPECT_EQ(p.strips[2].next_header_x(), 204);
  // Each span's colour and depth pixels are the dense row's.
  for (int s = 0; s < 2; ++s) {
    const ParsedStrip& st = p.strips[static_cast<std::size_t>(s)];
    const int x0 = st.header.x - 100;
    for (int i = 0; i < st.header.width; ++i) {
      const std::size_t at = 3 * static_cast<std::size_t>(st.source_x + i);
      const std::size_t dat = 3 * static_cast<std::size_t>(st.depth_x() + i);
      EXPECT_EQ(p.line[at], static_cast<std::uint8_t>(x0 + i));
      EXPECT_EQ(p.line[at + 1], 100);
      EXPECT_EQ(p.line[dat + 2], 5);
    }
  }
  // The SKIP's pixels are black.
  for (int x = 50; x < 204; ++x) EXPECT_EQ(p.line[3 * static_cast<std::size_t>(x)], 0);
}

TEST(SparseDepthRow, AnEmptyRowIsOneSkipAndAFullRowStaysDense) {
  const Row empty(drawn(30, {}));
  const Packed e = pack(empty, empty.spans());
  ASSERT_EQ(e.strips.size(), 1u);
  EXPECT_EQ(e.strips[0].header.op, StripOp::Skip);
  EXPECT_EQ(e.strips[0].header.width, 62);  // 4 + 60 - 2, as below a DEPTH tile (spec §7)
  const Row full(drawn(30, {{0, 30}}));
  const Packed f = pack(full, full.spans());
  ASSERT_EQ(f.strips.size(), 1u);
  EXPECT_TRUE(f.strips[0].is(ExtKind::Depth));
  EXPECT_EQ(f.strips[0].header.width, 30);
  EXPECT_EQ(f.strips[0].header.x, 100);
}

TEST(SparseDepthRow, AWidenedSpanFillsTheRowExactly) {
  const Row row(drawn(10, {{0, 9}}));
  const Packed p = pack(row, row.spans());
  ASSERT_EQ(p.strips.size(), 1u);
  EXPECT_EQ(p.strips[0].header.width, 10);
  EXPECT_EQ(p.strips[0].next_header_x(), 24);
  EXPECT_EQ(p.errors.total(), 0u);
}

TEST(SparseDepthRow, RandomRowsFillTheirColumnsAndSendEveryDrawnPixelOnce) {
  // Rows of 1..300 pixels with drawn runs and gaps of random lengths: the sparse row parses
  // with no error, ends exactly where the dense one did, and every drawn pixel arrives once,
  // with its own colour and depth, at its own column.
  std::mt19937 random(53);
  for (int trial = 0; trial < 2000; ++trial) {
    const int w = std::uniform_int_distribution<int>(1, 300)(random);
    std::vector<std::uint32_t> depths(static_cast<std::size_t>(w), kFar);
    std::uniform_int_distribution<int> run(1, 40);
    bool on = random() % 2 == 0;
    for (int x = 0; x < w;) {
      const int n = run(random);
      for (int k = x; k < std::min(w, x + n); ++k) {
        depths[static_cast<std::size_t>(k)] = on ? static_cast<std::uint32_t>(k) : kFar;
      }
      x += n;
      on = !on;
    }
    const Row row(depths);
    const Packed p = pack(row, row.spans());
    ASSERT_EQ(p.errors.total(), 0u) << "trial " << trial;
    std::vector<int> arrived(static_cast<std::size_t>(w), 0);
    int end = 0;
    for (const ParsedStrip& s : p.strips) {
      end = s.next_header_x();
      if (!s.is(ExtKind::Depth)) continue;
      for (int i = 0; i < s.header.width; ++i) {
        const int x = s.header.x - 100 + i;
        ASSERT_GE(x, 0);
        ASSERT_LT(x, w);
        ++arrived[static_cast<std::size_t>(x)];
        const std::size_t at = 3 * static_cast<std::size_t>(s.source_x + i);
        const std::size_t dat = 3 * static_cast<std::size_t>(s.depth_x() + i);
        EXPECT_EQ(p.line[at], static_cast<std::uint8_t>(x));
        const std::uint32_t d = std::uint32_t{p.line[dat]} << 16 |
                                std::uint32_t{p.line[dat + 1]} << 8 | p.line[dat + 2];
        EXPECT_EQ(d, depths[static_cast<std::size_t>(x)]);
      }
    }
    EXPECT_EQ(end, 4 + 2 * w) << "trial " << trial << " w " << w;
    for (int x = 0; x < w; ++x) {
      EXPECT_LE(arrived[static_cast<std::size_t>(x)], 1) << "trial " << trial << " x " << x;
      if (depths[static_cast<std::size_t>(x)] != kFar) {
        EXPECT_EQ(arrived[static_cast<std::size_t>(x)], 1) << "trial " << trial << " x " << x;
      }
    }
  }
}

}  // namespace
}  // namespace l2
