// Any bytes as input frames: the router must not crash, hang or touch memory outside its
// buffers (this suite runs under ASan+UBSan), must count every malformed strip, and must give
// the same result with any number of workers. Bounded to a few seconds.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/frame_builder.hpp"
#include "lightning2_emu/router.hpp"

namespace l2 {
namespace {

struct FuzzCase {
  std::vector<DisplaySpec> displays;
  std::vector<RgbImage> frames;
};

// Valid packed frames, then mutated: random bytes, valid-looking headers with random fields,
// and strips redirected outside the displays.
FuzzCase make_fuzz_case(std::mt19937& rng) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  FuzzCase c;
  const int displays = uni(1, 4);
  for (int d = 0; d < displays; ++d) {
    c.displays.push_back({d * 2, uni(1, 90), uni(1, 40), uni(0, 1)});
  }
  const int inputs = uni(1, 4);
  for (int i = 0; i < inputs; ++i) {
    RgbImage frame(uni(1, 160), uni(1, 48));
    const int mode = uni(0, 2);
    if (mode == 0) {
      std::vector<std::uint8_t> bytes(frame.bytes().size());
      for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
      std::copy(bytes.begin(), bytes.end(), frame.data());
    } else {
      std::vector<testing::Tile> tiles;
      for (int t = uni(0, 8); t > 0; --t) {
        const DisplaySpec& d = c.displays[uni(0, displays - 1)];
        tiles.push_back({uni(0, 1) ? d.id : uni(0, 63), uni(0, d.width + 5), uni(0, d.height + 5),
                         uni(1, 40), uni(1, 20)});
      }
      testing::pack_frame(tiles, uni(0, 1) != 0, frame);  // may not fit: partly packed
      for (int m = uni(0, 30); m > 0; --m) {
        const int x = uni(0, frame.width() - 1), y = uni(0, frame.height() - 1);
        if (mode == 2 && frame.width() >= 2 && x + 1 < frame.width()) {
          // A header whose check is right but whose fields are anything.
          const std::uint64_t message = (std::uint64_t{rng()} << 13 ^ rng()) & ((1ull << 45) - 1);
          write_header_pixels(message << 3 | crc3(message), frame.row(y).data() + x * 3, 3);
        } else {
          frame.row(y)[uni(0, static_cast<int>(frame.stride()) - 1)] ^=
              static_cast<std::uint8_t>(1 << uni(0, 7));
        }
      }
    }
    c.frames.push_back(std::move(frame));
  }
  return c;
}

TEST(Fuzz, RandomAndMutatedFramesAreRoutedSafelyAndIdenticallyInParallel) {
  std::mt19937 rng(20261122);
  WorkerPool serial(1), parallel(3);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(4);
  int cases = 0;
  StripErrorCounts seen;
  for (; cases < 3000 && std::chrono::steady_clock::now() < deadline; ++cases) {
    const FuzzCase c = make_fuzz_case(rng);
    std::vector<InputFrame> views;
    for (const RgbImage& f : c.frames) views.push_back(InputFrame::of(f));
    Router a(Mesh(1, 1, {160, 48}), c.displays, serial, {7, 8, 9});
    Router b(Mesh(1, 1, {160, 48}), c.displays, parallel, {7, 8, 9});
    const RouteReport ra = a.route(views);
    const RouteReport rb = b.route(views);
    ASSERT_EQ(ra, rb) << "case " << cases;
    for (int d = 0; d < a.display_count(); ++d) {
      ASSERT_EQ(a.display(d).back(), b.display(d).back()) << "case " << cases;
      const DisplayFrameStats& s = ra.displays[d];
      EXPECT_LE(s.covered_pixels, s.pixels());
      // On a compositing display a pixel inside two strips may be written by neither (§7).
      if (!a.composites(d)) {
        EXPECT_LE(s.overdraw_pixels, s.covered_pixels);
      }
    }
    for (const InputFrameStats& in : ra.inputs) {
      // Every routed strip is a COPY, KEY or DEPTH; each is routed, missing or wholly clipped.
      EXPECT_LE(in.routed_strips + in.errors.missing_display,
                in.copy_strips + in.key_strips + in.depth_strips);
      seen += in.errors;
    }
  }
  EXPECT_GT(cases, 50);
  // The generator reaches every error kind, so each is exercised.
  EXPECT_GT(seen.check_errors, 0u);
  EXPECT_GT(seen.ext_unsupported, 0u);
  EXPECT_GT(seen.zero_width, 0u);
  EXPECT_GT(seen.truncations, 0u);
  EXPECT_GT(seen.missing_display, 0u);
  EXPECT_GT(seen.clips, 0u);
}

// The same frames through the whole emulator over many refreshes, parities at random.
TEST(Fuzz, EmulatorSurvivesRandomSequences) {
  std::mt19937 rng(7);
  for (int run = 0; run < 40; ++run) {
    FuzzCase c = make_fuzz_case(rng);
    EmulatorConfig config;
    config.mesh = Mesh(1, 1, {160, 48});
    config.displays = c.displays;
    config.workers = 2;
    Emulator emu(config);
    std::vector<InputFrame> views;
    for (int t = 0; t < 12; ++t) {
      if (rng() % 3 == 0)
        c = [&] {
          FuzzCase n = make_fuzz_case(rng);
          n.displays = c.displays;
          return n;
        }();
      views.clear();
      for (const RgbImage& f : c.frames) views.push_back(InputFrame::of(f));
      emu.tick(views);
    }
    std::uint64_t frames = 0;
    for (const auto& in : emu.report().inputs) {
      for (auto n : in.frames) frames += n;
    }
    EXPECT_EQ(frames, 12u * emu.report().inputs.size());
  }
}

}  // namespace
}  // namespace l2
