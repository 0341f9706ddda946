// The router against a reference that follows spec §3/§5 pixel by pixel: parse each scanline,
// paint every COPY strip in bus order, count writes per pixel. The router does the same with
// bands, prefetching, wide copies and interval arithmetic; whatever it does for speed, pixels and
// counts must come out the same. Random frames with overlapping tiles, RGB and RGBA, positive
// and negative strides, corrupted headers, and frames written in one or several write() calls.
// Bounded to about two seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <random>

#include "lightning2_emu/frame_builder.hpp"
#include "lightning2_emu/router.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2 {
namespace {

// One display of the reference: colour and depth per pixel (spec §7), whether a strip wrote it,
// and how many strips covered it this frame.
struct RefDisplay {
  DisplaySpec spec;
  RgbImage image;
  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> written;
  std::vector<int> strips_over;
  std::uint64_t strips = 0;
};

// A strip a write() call routed, kept until the frame is finished: then every strip of the
// frame is applied in pixel-bus order, whichever call wrote it.
struct RefStrip {
  int input;
  RefDisplay* display;
  StripOp op;
  Extension extension;
  int x, y, length;
  const std::uint8_t* colour;  // colour pixel k at colour + k * bpp
  const std::uint8_t* depth;   // DEPTH: depth pixel k at depth + k * bpp
  int bpp;
};

// A raw 48-bit value in two pixels of a frame, R0 G0 B0 R1 G1 B1 (§2).
void frame_raw(RgbImage& frame, int x, int y, std::uint64_t v) {
  frame.set(x, y,
            Rgb{static_cast<std::uint8_t>(v >> 40), static_cast<std::uint8_t>(v >> 32),
                static_cast<std::uint8_t>(v >> 24)});
  frame.set(x + 1, y,
            Rgb{static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
                static_cast<std::uint8_t>(v)});
}
void frame_header(RgbImage& frame, int x, int y, const StripHeader& h) {
  frame_raw(frame, x, y, encode(h));
}

std::uint32_t rgb_value(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2];
}

class Reference {
 public:
  Reference(std::vector<DisplaySpec> displays, Rgb background) : background_(background) {
    for (const DisplaySpec& d : displays) {
      displays_.push_back({d, RgbImage(d.width, d.height, background), {}, {}, {}, 0});
    }
    for (RefDisplay& d : displays_) start_frame(d);
  }

  // Parses every frame, counting what the router's scan() counts.
  std::vector<InputFrameStats> scan(std::span<const InputFrame> frames) {
    std::vector<InputFrameStats> stats(frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      stats[i].input = static_cast<int>(i);
      stats[i].present = frames[i].present();
      if (stats[i].present) for_each_strip(frames[i], static_cast<int>(i), stats[i], false);
    }
    return stats;
  }

  // Keeps the strips of the chosen inputs for finish().
  void write(std::span<const InputFrame> frames, const std::vector<std::uint8_t>& route) {
    for (std::size_t i = 0; i < frames.size(); ++i) {
      if (!route[i] || !frames[i].present()) continue;
      InputFrameStats ignored;
      for_each_strip(frames[i], static_cast<int>(i), ignored, true);
    }
  }

  // Applies the frame's strips in bus order (inputs ascending, scan order within an input) as
  // §7 says; background where nothing was written; coverage (pixels written) and overdraw
  // (pixels inside two or more strips) counted pixel by pixel.
  std::vector<DisplayFrameStats> finish() {
    std::stable_sort(kept_.begin(), kept_.end(),
                     [](const RefStrip& a, const RefStrip& b) { return a.input < b.input; });
    for (const RefStrip& s : kept_) apply(s);
    kept_.clear();
    std::vector<DisplayFrameStats> out;
    for (RefDisplay& d : displays_) {
      DisplayFrameStats st{d.spec.id, d.spec.width, d.spec.height, d.strips, 0, 0};
      for (int y = 0; y < d.spec.height; ++y) {
        for (int x = 0; x < d.spec.width; ++x) {
          const std::size_t p = static_cast<std::size_t>(y) * d.spec.width + x;
          if (!d.written[p]) d.image.set(x, y, background_);
          st.covered_pixels += d.written[p];
          st.overdraw_pixels += d.strips_over[p] >= 2;
        }
      }
      out.push_back(st);
      start_frame(d);
    }
    return out;
  }

  const RgbImage& image(int d) const { return displays_[d].image; }

 private:
  static void start_frame(RefDisplay& d) {
    const std::size_t pixels = static_cast<std::size_t>(d.spec.width) * d.spec.height;
    d.depth.assign(pixels, 0xFFFFFF);
    d.written.assign(pixels, 0);
    d.strips_over.assign(pixels, 0);
    d.strips = 0;
  }

  static void apply(const RefStrip& s) {
    RefDisplay& d = *s.display;
    for (int k = 0; k < s.length; ++k) {
      const std::size_t p = static_cast<std::size_t>(s.y) * d.spec.width + s.x + k;
      const std::uint8_t* c = s.colour + k * s.bpp;
      ++d.strips_over[p];
      std::uint32_t depth = 0;
      if (s.op == StripOp::Ext && s.extension.kind == ExtKind::Key) {
        if (rgb_value(c) == s.extension.key) continue;  // transparent
      } else if (s.op == StripOp::Ext) {
        depth = rgb_value(s.depth + k * s.bpp);
        if (!(depth < d.depth[p])) continue;
      }
      d.image.set(s.x + k, s.y, Rgb{c[0], c[1], c[2]});
      d.depth[p] = depth;
      d.written[p] = 1;
    }
  }

  // Counts every strip of the frame; with `keep`, keeps the routed ones for finish().
  void for_each_strip(const InputFrame& f, int input, InputFrameStats& st, bool keep) {
    for (int y = 0; y < f.height; ++y) {
      parse_scanline(f.row(y), f.width, f.bytes_per_pixel, st.errors, [&](const ParsedStrip& s) {
        st.parities |= static_cast<std::uint8_t>(s.header.frame ? 2 : 1);
        if (s.header.op == StripOp::Skip) {
          ++st.skip_strips;
          return;
        }
        if (s.header.op == StripOp::Copy) {
          ++st.copy_strips;
        } else if (s.extension.kind == ExtKind::Key) {
          ++st.key_strips;
        } else {
          ++st.depth_strips;
        }
        RefDisplay* d = find(s.header.display);
        if (!d) {
          ++st.errors.missing_display;
          return;
        }
        if (s.length == 0) return;
        if (s.header.x >= d->spec.width || s.header.y >= d->spec.height) {
          ++st.errors.clips;
          return;
        }
        if (s.header.x + s.length > d->spec.width) ++st.errors.clips;
        const int length = std::min(s.length, d->spec.width - s.header.x);
        ++st.routed_strips;
        st.displays_fed |= std::uint64_t{1} << s.header.display;
        if (!keep) return;
        ++d->strips;
        const std::uint8_t* row = f.row(y);
        kept_.push_back(
            {input, d, s.header.op, s.extension, s.header.x, s.header.y, length,
             row + static_cast<std::ptrdiff_t>(s.source_x) * f.bytes_per_pixel,
             row + static_cast<std::ptrdiff_t>(s.source_x + s.header.width) * f.bytes_per_pixel,
             f.bytes_per_pixel});
      });
    }
  }

  RefDisplay* find(int id) {
    for (RefDisplay& d : displays_) {
      if (d.spec.id == id) return &d;
    }
    return nullptr;
  }

  Rgb background_;
  std::vector<RefDisplay> displays_;
  std::vector<RefStrip> kept_;
};

// A scanned-out frame held as the router may meet it: RGB or RGBA, rows top-down or bottom-up.
struct HeldFrame {
  std::vector<std::uint8_t> bytes;
  InputFrame view;
};

HeldFrame hold(const RgbImage& rgb, int bytes_per_pixel, bool bottom_up, int padding) {
  HeldFrame h;
  const int w = rgb.width(), ht = rgb.height();
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(w) * bytes_per_pixel + padding;
  h.bytes.assign(static_cast<std::size_t>(stride) * ht, 0xEE);
  for (int y = 0; y < ht; ++y) {
    std::uint8_t* row = h.bytes.data() + (bottom_up ? ht - 1 - y : y) * stride;
    for (int x = 0; x < w; ++x) {
      std::copy_n(rgb.row(y).data() + x * 3, 3, row + x * bytes_per_pixel);
    }
  }
  const std::uint8_t* row0 = h.bytes.data() + (bottom_up ? (ht - 1) * stride : 0);
  h.view = {row0, bottom_up ? -stride : stride, w, ht, bytes_per_pixel};
  return h;
}

// Strip pixels that differ from input to input and place to place in the frame: where strips
// overlap on a display, only the right write order gives the right picture.
void colour_strips(RgbImage& rgb, int input) {
  for (int y = 0; y < rgb.height(); ++y) {
    StripErrorCounts ignored;
    parse_scanline(rgb.row(y).data(), rgb.width(), 3, ignored, [&](const ParsedStrip& s) {
      for (int x = s.source_x; x < s.source_x + s.length; ++x)
        rgb.set(x, y, testing::pattern(input + 100, x, y));
    });
  }
}

struct ReferenceCase {
  std::vector<DisplaySpec> displays;
  std::vector<HeldFrame> frames;  // an empty one: no signal
};

// Tiles from a few displays, overlapping and sometimes leaving the display, packed per §4 and
// a few bytes flipped now and then.
ReferenceCase make_reference_case(std::mt19937& rng) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  ReferenceCase c;
  for (int d = uni(1, 3); d > 0; --d) {
    // Some displays tall enough to have many bands of rows, so runs cross band edges.
    c.displays.push_back({static_cast<int>(c.displays.size()) * 3, uni(1, 300),
                          uni(0, 3) ? uni(1, 40) : uni(41, 200), 0});
  }
  for (int i = uni(1, 4); i > 0; --i) {
    if (uni(0, 9) == 0) {
      c.frames.emplace_back();
      continue;
    }
    std::vector<testing::Tile> tiles;
    for (int t = uni(0, 10); t > 0; --t) {
      const DisplaySpec& d = c.displays[uni(0, static_cast<int>(c.displays.size()) - 1)];
      const int id = uni(0, 12) ? d.id : 1;
      if (uni(0, 3)) {  // inside the display, as tiles mostly are
        const int x = uni(0, d.width - 1), y = uni(0, d.height - 1);
        tiles.push_back(
            {id, x, y, uni(1, std::min(140, d.width - x)), uni(1, std::min(40, d.height - y))});
      } else {  // anywhere: partly or wholly outside
        tiles.push_back({id, uni(0, d.width), uni(0, d.height), uni(1, 140), uni(1, 40)});
      }
    }
    RgbImage rgb(uni(2, 320), uni(1, 96));
    testing::pack_frame(tiles, uni(0, 1) != 0, rgb);  // may not all fit
    colour_strips(rgb, static_cast<int>(c.frames.size()));
    for (int m = uni(0, 3) == 0 ? uni(1, 4) : 0; m > 0; --m) {
      const int y = uni(0, rgb.height() - 1), at = uni(0, static_cast<int>(rgb.stride()) - 1);
      if (uni(0, 1)) {
        rgb.row(y)[at] ^= static_cast<std::uint8_t>(1 << uni(0, 7));
      } else {  // the scanline ends early: black from here on reads as END
        std::fill(rgb.row(y).begin() + at, rgb.row(y).end(), std::uint8_t{0});
      }
    }
    c.frames.push_back(hold(rgb, uni(0, 1) ? 4 : 3, uni(0, 1) != 0, uni(0, 1) * 8));
  }
  return c;
}

struct CaseTotals {
  int cases = 0;
  std::uint64_t overdrawn = 0, covered = 0, multi_write_frames = 0;
};

// Routes each case twice on one router (the second frame is predicted from the first), in one
// write() call or several with inputs at random (inputs delivering at different refreshes), and
// compares counts and pixels with the reference.
template <class MakeCase>
void check_cases(unsigned seed, MakeCase make_case, CaseTotals& totals) {
  std::mt19937 rng(seed);
  WorkerPool pool(2);
  const Rgb background{3, 4, 5};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  int& cases = totals.cases;
  // Two seconds' worth of cases, but never fewer than 40 (sanitizer builds on a busy machine).
  for (; cases < 1500 && (cases < 40 || std::chrono::steady_clock::now() < deadline); ++cases) {
    const ReferenceCase c = make_case(rng);
    std::vector<InputFrame> views;
    for (const HeldFrame& f : c.frames) views.push_back(f.bytes.empty() ? InputFrame{} : f.view);
    Router router(Mesh(1, 1, {320, 96}), c.displays, pool, background);
    Reference ref(c.displays, background);
    std::vector<int> all_displays(c.displays.size());
    for (std::size_t d = 0; d < all_displays.size(); ++d) all_displays[d] = static_cast<int>(d);
    // Two frames on the same router: the second must not see the first.
    for (int frame = 0; frame < 2; ++frame) {
      router.scan(views);
      const std::vector<InputFrameStats> expected = ref.scan(views);
      for (std::size_t i = 0; i < views.size(); ++i) {
        ASSERT_EQ(router.scanned(static_cast<int>(i)), expected[i]) << "case " << cases;
      }
      const int calls = std::uniform_int_distribution<int>(1, 3)(rng);
      totals.multi_write_frames += calls > 1;
      for (int call = 0; call < calls; ++call) {
        std::vector<std::uint8_t> route(views.size(), 1);
        if (calls > 1) {
          for (auto& r : route) r = static_cast<std::uint8_t>(rng() % 2);
        }
        router.write(route);
        ref.write(views, route);
      }
      std::vector<DisplayFrameStats> got;
      router.finish(all_displays, got);
      const std::vector<DisplayFrameStats> want = ref.finish();
      ASSERT_EQ(got, want) << "case " << cases << " frame " << frame;
      for (std::size_t d = 0; d < c.displays.size(); ++d) {
        ASSERT_EQ(router.display(static_cast<int>(d)).back(), ref.image(static_cast<int>(d)))
            << "case " << cases << " frame " << frame << " display " << d;
        totals.overdrawn += want[d].overdraw_pixels;
        totals.covered += want[d].covered_pixels;
      }
    }
  }
}

TEST(Reference, RouterMatchesThePixelByPixelReference) {
  CaseTotals totals;
  check_cases(4242, make_reference_case, totals);
  EXPECT_GT(totals.overdrawn, 0u);  // the cases do overlap
  EXPECT_GT(totals.multi_write_frames, 0u);
}

// A tile of a compositing wall: COPY, KEY (with its key colour) or DEPTH.
struct LayerTile {
  testing::Tile tile;
  int kind;  // 0 COPY, 1 KEY, 2 DEPTH
  std::uint32_t key;
};

Rgb colour_of(std::uint32_t v) {
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
          static_cast<std::uint8_t>(v)};
}

// Packs layer tiles as §7's packing says, written here from the spec (gaps of 2 or 4 pixels,
// payloads of w or 2w, SKIPs below short tiles); tiles that do not fit are left out. Colours come
// from a small palette that holds the key colours, depths from a few values (ties, 0, the far
// plane) and any.
void pack_layers(const std::vector<LayerTile>& tiles, RgbImage& frame, std::mt19937& rng) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const std::uint32_t palette[] = {0x00FF00, 0xFF00FF, 0x102030, 0x405060, 0xFFFFFF, 0x00FF01};
  const std::uint32_t depths[] = {0, 3, 3, 9, 9, 0xFFFFFE, 0xFFFFFF, 0xFFFFFF};
  struct Placed {
    LayerTile t;
    int x;
  };
  std::vector<std::vector<Placed>> rows(1);
  int x = 0;
  for (const LayerTile& t : tiles) {
    const int gap = t.kind ? 4 : 2, p = t.tile.w * (t.kind == 2 ? 2 : 1);
    if (gap + p > frame.width()) continue;
    if (x + gap + p > frame.width()) {
      rows.emplace_back();
      x = 0;
    }
    rows.back().push_back({t, x});
    x += gap + p;
  }
  int y0 = 0;
  for (const auto& row : rows) {
    int h = 0;
    for (const Placed& pl : row) h = std::max(h, pl.t.tile.h);
    if (y0 + h > frame.height()) break;
    for (int r = 0; r < h; ++r) {
      const int y = y0 + r;
      for (const Placed& pl : row) {
        const testing::Tile& t = pl.t.tile;
        const int gap = pl.t.kind ? 4 : 2;
        if (r >= t.h) {
          frame_header(frame, pl.x, y,
                       StripHeader::skip(false, t.w * (pl.t.kind == 2 ? 2 : 1) + gap - 2));
          continue;
        }
        StripHeader hd = StripHeader::copy(false, t.display, t.dx, t.dy + r, t.w);
        if (pl.t.kind) hd.op = StripOp::Ext;
        frame_header(frame, pl.x, y, hd);
        if (pl.t.kind) {
          const Extension e = pl.t.kind == 1 ? Extension::key_colour(pl.t.key) : Extension::depth();
          frame_raw(frame, pl.x + 2, y, encode(e));
        }
        for (int k = 0; k < t.w; ++k) {
          frame.set(pl.x + gap + k, y,
                    colour_of(uni(0, 2) ? palette[uni(0, 5)] : rng() & 0xFFFFFF));
          if (pl.t.kind == 2) {
            const std::uint32_t d = uni(0, 3) ? depths[uni(0, 7)] : rng() & 0xFFFFFF;
            frame.set(pl.x + gap + t.w + k, y, colour_of(d));
          }
        }
      }
    }
    y0 += h;
  }
}

// Walls of COPY, KEY and DEPTH tiles: every input draws layers over the same few areas of the
// displays, so strips of different inputs and kinds meet on the same pixels.
ReferenceCase make_layer_case(std::mt19937& rng) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  ReferenceCase c;
  for (int d = uni(1, 2); d > 0; --d) {
    c.displays.push_back({static_cast<int>(c.displays.size()) * 3, uni(1, 120), uni(1, 60), 0});
  }
  std::vector<testing::Tile> areas;
  for (int a = uni(1, 4); a > 0; --a) {
    const DisplaySpec& d = c.displays[uni(0, static_cast<int>(c.displays.size()) - 1)];
    const int x = uni(0, d.width - 1), y = uni(0, d.height - 1);
    areas.push_back({uni(0, 12) ? d.id : 1, x, y, uni(1, std::min(60, d.width - x + uni(0, 4))),
                     uni(1, std::min(30, d.height - y))});
  }
  for (int i = uni(1, 4); i > 0; --i) {
    if (uni(0, 12) == 0) {
      c.frames.emplace_back();
      continue;
    }
    std::vector<LayerTile> tiles;
    for (int t = uni(0, 6); t > 0; --t) {
      const int kind = uni(0, 4) == 0 ? 0 : uni(0, 2) == 0 ? 1 : 2;
      tiles.push_back({areas[uni(0, static_cast<int>(areas.size()) - 1)], kind,
                       uni(0, 1) ? 0x00FF00u : 0xFF00FFu});
    }
    RgbImage rgb(uni(8, 320), uni(1, 96));
    pack_layers(tiles, rgb, rng);
    if (uni(0, 5) == 0) {  // a flipped bit now and then
      const int y = uni(0, rgb.height() - 1), at = uni(0, static_cast<int>(rgb.stride()) - 1);
      rgb.row(y)[at] ^= static_cast<std::uint8_t>(1 << uni(0, 7));
    }
    c.frames.push_back(hold(rgb, uni(0, 1) ? 4 : 3, uni(0, 1) != 0, uni(0, 1) * 8));
  }
  return c;
}

TEST(Reference, CompositingMatchesTheBusOrderComposite) {
  CaseTotals totals;
  check_cases(2020, make_layer_case, totals);
  EXPECT_GT(totals.overdrawn, 0u);
  EXPECT_GT(totals.covered, 0u);
  EXPECT_GT(totals.multi_write_frames, 0u);
}

}  // namespace
}  // namespace l2
