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

#include "frame_builder.hpp"
#include "lightning2_emu/router.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2 {
namespace {

// One display of the reference: pixels, and per pixel the strips that covered it this frame
// and the highest input an earlier write() call wrote it with.
struct RefDisplay {
  DisplaySpec spec;
  RgbImage image;
  std::vector<int> writes;
  std::vector<int> earlier_input;
  std::uint64_t strips = 0;
};

class Reference {
 public:
  Reference(std::vector<DisplaySpec> displays, Rgb background) : background_(background) {
    for (const DisplaySpec& d : displays) {
      displays_.push_back({d, RgbImage(d.width, d.height, background), {}, {}, 0});
      start_frame(displays_.back());
    }
  }

  // Parses every frame, counting what the router's scan() counts.
  std::vector<InputFrameStats> scan(std::span<const InputFrame> frames) {
    std::vector<InputFrameStats> stats(frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      stats[i].input = static_cast<int>(i);
      stats[i].present = frames[i].present();
      if (stats[i].present) for_each_strip(frames[i], stats[i], nullptr);
    }
    return stats;
  }

  // Paints the strips of the chosen inputs, ascending; a pixel an earlier call wrote with a
  // higher input keeps that input's colour.
  void write(std::span<const InputFrame> frames, const std::vector<std::uint8_t>& route) {
    std::vector<std::vector<int>> written(displays_.size());
    for (std::size_t d = 0; d < displays_.size(); ++d) written[d] = displays_[d].earlier_input;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      if (!route[i] || !frames[i].present()) continue;
      InputFrameStats ignored;
      for_each_strip(frames[i], ignored, [&](RefDisplay& d, int x, int y, const std::uint8_t* px) {
        const std::size_t p = static_cast<std::size_t>(y) * d.spec.width + x;
        ++d.writes[p];
        const std::size_t index = static_cast<std::size_t>(&d - displays_.data());
        written[index][p] = std::max(written[index][p], static_cast<int>(i));
        if (d.earlier_input[p] > static_cast<int>(i)) return;
        d.image.set(x, y, Rgb{px[0], px[1], px[2]});
      });
    }
    for (std::size_t d = 0; d < displays_.size(); ++d) displays_[d].earlier_input = written[d];
  }

  // Background where nothing was written; coverage and overdraw counted pixel by pixel.
  std::vector<DisplayFrameStats> finish() {
    std::vector<DisplayFrameStats> out;
    for (RefDisplay& d : displays_) {
      DisplayFrameStats st{d.spec.id, d.spec.width, d.spec.height, d.strips, 0, 0};
      for (int y = 0; y < d.spec.height; ++y) {
        for (int x = 0; x < d.spec.width; ++x) {
          const int n = d.writes[static_cast<std::size_t>(y) * d.spec.width + x];
          if (n == 0) d.image.set(x, y, background_);
          st.covered_pixels += n >= 1;
          st.overdraw_pixels += n >= 2;
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
    d.writes.assign(pixels, 0);
    d.earlier_input.assign(pixels, -1);
    d.strips = 0;
  }

  // Calls paint(display, x, y, source pixel) for every pixel of every routed strip, in scan
  // order, and counts the strips; paint == nullptr only counts.
  template <class Paint>
  void for_each_strip(const InputFrame& f, InputFrameStats& st, Paint paint) {
    for (int y = 0; y < f.height; ++y) {
      parse_scanline(f.row(y), f.width, f.bytes_per_pixel, st.errors, [&](const ParsedStrip& s) {
        if (s.header.op == StripOp::Ext) {  // not composited: the rest of the scanline dropped
          ++st.errors.ext_unsupported;
          return false;
        }
        st.parities |= static_cast<std::uint8_t>(s.header.frame ? 2 : 1);
        if (s.header.op == StripOp::Skip) {
          ++st.skip_strips;
          return true;
        }
        ++st.copy_strips;
        RefDisplay* d = find(s.header.display);
        if (!d) {
          ++st.errors.missing_display;
          return true;
        }
        if (s.length == 0) return true;
        if (s.header.x >= d->spec.width || s.header.y >= d->spec.height) {
          ++st.errors.clips;
          return true;
        }
        if (s.header.x + s.length > d->spec.width) ++st.errors.clips;
        const int length = std::min(s.length, d->spec.width - s.header.x);
        ++st.routed_strips;
        st.displays_fed |= std::uint64_t{1} << s.header.display;
        if constexpr (!std::is_same_v<Paint, std::nullptr_t>) {
          ++d->strips;
          for (int k = 0; k < length; ++k) {
            paint(*d, s.header.x + k, s.header.y,
                  f.row(y) + static_cast<std::ptrdiff_t>(s.source_x + k) * f.bytes_per_pixel);
          }
        }
        return true;
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

TEST(Reference, RouterMatchesThePixelByPixelReference) {
  std::mt19937 rng(4242);
  WorkerPool pool(2);
  const Rgb background{3, 4, 5};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  int cases = 0;
  std::uint64_t overdrawn = 0, multi_write_frames = 0;
  // Two seconds' worth of cases, but never fewer than 40 (sanitizer builds on a busy machine).
  for (; cases < 1500 && (cases < 40 || std::chrono::steady_clock::now() < deadline); ++cases) {
    const ReferenceCase c = make_reference_case(rng);
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
      // One write() call with every input, or several with inputs at random (a frame whose
      // inputs arrive at different refreshes).
      const int calls = std::uniform_int_distribution<int>(1, 3)(rng);
      multi_write_frames += calls > 1;
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
        overdrawn += want[d].overdraw_pixels;
      }
    }
  }
  EXPECT_GT(overdrawn, 0u);  // the cases do overlap
  EXPECT_GT(multi_write_frames, 0u);
}

}  // namespace
}  // namespace l2
