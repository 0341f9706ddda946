// Frames the router predicts from the last one (router.hpp) must route exactly as parsed ones:
// the same counts, decisions, swaps and pixels, whatever changed between the two frames. Each
// test runs two emulators side by side on the same frames, one predicting and one parsing
// every frame, and compares them at every refresh.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/frame_builder.hpp"

namespace l2 {
namespace {

using testing::FrameBuilder;

// The two emulators, fed the same frames.
class SideBySide {
 public:
  explicit SideBySide(EmulatorConfig config)
      : predicting_(with(config, true)), parsing_(with(config, false)) {}

  // One refresh of both; fails the test where they differ.
  void tick(const std::vector<InputFrame>& frames, const std::string& where) {
    const Emulator::Tick& a = predicting_.tick(frames);
    const Emulator::Tick& b = parsing_.tick(frames);
    ASSERT_EQ(a.swapped_groups, b.swapped_groups) << where;
    ASSERT_EQ(a.ready_inputs, b.ready_inputs) << where;
    ASSERT_EQ(a.kinds, b.kinds) << where;
    ASSERT_EQ(a.inputs, b.inputs) << where;
    ASSERT_EQ(a.completed_groups, b.completed_groups) << where;
    ASSERT_EQ(a.completed, b.completed) << where;
    for (int d = 0; d < predicting_.router().display_count(); ++d) {
      const int id = predicting_.router().display(d).id();
      ASSERT_EQ(predicting_.shown(id), parsing_.shown(id)) << where << ", display " << id;
    }
  }

  const Router::PredictionCounts& predictions() const { return predicting_.router().predictions(); }
  const Router::PredictionCounts& parser_predictions() const {
    return parsing_.router().predictions();
  }

 private:
  static EmulatorConfig with(EmulatorConfig c, bool predict) {
    c.predict_layouts = predict;
    return c;
  }
  Emulator predicting_, parsing_;
};

// Display 0 (16x4) fed by input 0 on rows 0-1 and input 1 on rows 2-3, one swap group.
EmulatorConfig two_inputs() {
  EmulatorConfig c;
  c.mesh = Mesh(1, 1, {64, 8});
  c.displays = {{0, 16, 4, 0}};
  c.workers = 2;
  return c;
}

// Rows y0, y0+1 of display 0, `shift` columns to the right, in colour c.
RgbImage two_rows(int y0, int shift, Rgb c, bool parity) {
  FrameBuilder b(64, 8);
  for (int k = 0; k < 2; ++k) b.copy_fill(0, k, 0, shift, y0 + k, 16 - shift, c, parity);
  return b.image();
}

std::vector<InputFrame> frames_of(const std::vector<RgbImage>& images) {
  std::vector<InputFrame> v;
  for (const RgbImage& i : images) v.push_back(InputFrame::of(i));
  return v;
}

TEST(Prediction, HeldWhenOnlyTheParityAndThePixelsChange) {
  SideBySide emu(two_inputs());
  for (int t = 0; t < 6; ++t) {
    const Rgb c{static_cast<std::uint8_t>(10 * t), 20, 30};
    emu.tick(frames_of({two_rows(0, 0, c, t % 2), two_rows(2, 0, c, t % 2)}),
             "refresh " + std::to_string(t));
  }
  // Refresh 0 is parsed; both inputs of the five after it predicted, and right.
  EXPECT_EQ(emu.predictions().predicted, 10u);
  EXPECT_EQ(emu.predictions().mispredicted, 0u);
  EXPECT_EQ(emu.parser_predictions().predicted, 0u);
}

TEST(Prediction, AMovedStripIsFoundWhileWritingAndTheFrameParsed) {
  SideBySide emu(two_inputs());
  const Rgb c{9, 99, 199};
  emu.tick(frames_of({two_rows(0, 0, c, false), two_rows(2, 0, c, false)}), "refresh 0");
  // Input 1's strips now start at column 3: the same header positions, other x fields.
  emu.tick(frames_of({two_rows(0, 0, c, true), two_rows(2, 3, c, true)}), "refresh 1");
  emu.tick(frames_of({two_rows(0, 0, c, false), two_rows(2, 3, c, false)}), "refresh 2");
  EXPECT_EQ(emu.predictions().predicted, 4u);
  EXPECT_EQ(emu.predictions().mispredicted, 1u);
  EXPECT_EQ(emu.predictions().checked_first, 0u);
}

TEST(Prediction, ATornFrameIsFoundAndNotRouted) {
  SideBySide emu(two_inputs());
  const Rgb c{1, 2, 3};
  emu.tick(frames_of({two_rows(0, 0, c, false), two_rows(2, 0, c, false)}), "refresh 0");
  // Input 0's second strip keeps the old parity: torn, which the prediction (parity of the
  // first strip for all) does not hold.
  FrameBuilder torn(64, 8);
  torn.copy_fill(0, 0, 0, 0, 0, 16, Rgb{200, 0, 0}, true);
  torn.copy_fill(0, 1, 0, 0, 1, 16, Rgb{200, 0, 0}, false);
  emu.tick(frames_of({torn.image(), two_rows(2, 0, c, true)}), "refresh 1");
  emu.tick(frames_of({two_rows(0, 0, c, true), two_rows(2, 0, c, true)}), "refresh 2");
  EXPECT_EQ(emu.predictions().mispredicted, 1u);
}

// Input 0 delivers a frame a refresh before input 1, whose predicted strips (rows y1, y1+1)
// turn out moved. The display keeps input 0's strips, written a refresh earlier, and shows
// what a parse gives.
Router::PredictionCounts late_input_moves(int y1) {
  SideBySide emu(two_inputs());
  const Rgb c{5, 6, 7};
  emu.tick(frames_of({two_rows(0, 0, c, false), two_rows(y1, 0, c, false)}), "refresh 0");
  // Input 0 delivers its next frame, input 1 is late: its old frame again (a repeat).
  emu.tick(frames_of({two_rows(0, 0, c, true), two_rows(y1, 0, c, false)}), "refresh 1");
  // Input 1's frame arrives, its strips moved, while input 0's are in the back buffer.
  emu.tick(frames_of({two_rows(0, 0, c, true), two_rows(y1, 5, Rgb{50, 60, 70}, true)}),
           "refresh 2");
  emu.tick(frames_of({two_rows(0, 0, c, false), two_rows(y1, 5, c, false)}), "refresh 3");
  return emu.predictions();
}

TEST(Prediction, AMissBesideAnEarlierRefreshsStripsIsUndoneAroundThem) {
  // Input 1 on rows 2-3, clear of input 0's rows 0-1: checked while copied; the miss is undone
  // by dropping only what refresh 2 wrote.
  const Router::PredictionCounts counts = late_input_moves(2);
  EXPECT_EQ(counts.checked_first, 0u);
  EXPECT_EQ(counts.mispredicted, 1u);
}

TEST(Prediction, CheckedBeforeWritingWhereItsStripsOverlapAnEarlierRefreshs) {
  // Input 1 on rows 1-2, over input 0's row 1: a wrong prediction copied there would overwrite
  // input 0's strip, so at refresh 2 both predictions are checked before anything is written.
  const Router::PredictionCounts counts = late_input_moves(1);
  EXPECT_EQ(counts.checked_first, 2u);
  EXPECT_EQ(counts.mispredicted, 1u);
}

// Random walls and frame streams: each refresh an input repeats its frame, flips its parity,
// has a byte flipped (a header or a pixel), gets a header with random fields, is torn, packs
// new tiles, or goes dark. Some inputs are RGBA.
struct Stream {
  std::vector<testing::Tile> tiles;
  bool parity = false;
  bool rgba = false;
  bool dark = false;
  RgbImage frame;
  std::vector<std::uint8_t> rgba_bytes;
};

class RandomWall {
 public:
  explicit RandomWall(std::mt19937& rng) : rng_(rng) {
    const int displays = uni(1, 3);
    for (int d = 0; d < displays; ++d) {
      config_.displays.push_back({d * 3, uni(20, 120), uni(8, 40), uni(0, 1)});
    }
    config_.mesh = Mesh(1, 1, {kWidth, kHeight});
    config_.workers = 2;
    streams_.resize(uni(1, 4));
    for (Stream& s : streams_) {
      s.rgba = uni(0, 3) == 0;
      new_tiles(s);
    }
  }
  const EmulatorConfig& config() const { return config_; }

  std::vector<InputFrame> next() {
    std::vector<InputFrame> views;
    for (Stream& s : streams_) {
      change(s);
      views.push_back(view(s));
    }
    return views;
  }

 private:
  static constexpr int kWidth = 160, kHeight = 48;

  int uni(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  void new_tiles(Stream& s) {
    s.tiles.clear();
    for (int t = uni(1, 6); t > 0; --t) {
      const DisplaySpec& d =
          config_.displays[uni(0, static_cast<int>(config_.displays.size()) - 1)];
      const int w = uni(1, std::min(40, d.width)), h = uni(1, std::min(12, d.height));
      // Mostly inside the display (a clean frame, predicted next time), now and then not.
      const int slack = uni(0, 9) == 0 ? 6 : 0;
      s.tiles.push_back({d.id, uni(0, d.width - w + slack), uni(0, d.height - h + slack), w, h});
    }
    pack(s);
  }

  void pack(Stream& s) {
    s.frame = RgbImage(kWidth, kHeight);
    testing::pack_frame(s.tiles, s.parity, s.frame);
  }

  void change(Stream& s) {
    s.dark = false;
    switch (uni(0, 11)) {
      case 0:
      case 1:  // the same frame again
        break;
      case 2:
      case 3:
      case 4:
      case 5:  // the next frame of the same layout
        s.parity = !s.parity;
        pack(s);
        break;
      case 6: {  // a byte flipped: mostly a pixel, now and then a header
        auto row = s.frame.row(uni(0, kHeight - 1));
        row[uni(0, static_cast<int>(row.size()) - 1)] ^= static_cast<std::uint8_t>(1 << uni(0, 7));
        break;
      }
      case 7: {  // a header with a right check and any fields where tiles start
        const std::uint64_t message = (std::uint64_t{rng_()} << 13 ^ rng_()) & ((1ull << 45) - 1);
        write_header_pixels(message << 3 | crc3(message),
                            s.frame.row(uni(0, kHeight - 1)).data() + 3 * uni(0, kWidth - 2), 3);
        break;
      }
      case 8: {  // torn: the top from the next frame, the rest from this one
        RgbImage next(kWidth, kHeight);
        testing::pack_frame(s.tiles, !s.parity, next);
        for (int y = 0; y < uni(1, kHeight - 1); ++y) {
          std::copy(next.row(y).begin(), next.row(y).end(), s.frame.row(y).begin());
        }
        break;
      }
      case 9:
      case 10:  // a new layout
        s.parity = !s.parity;
        new_tiles(s);
        break;
      default:  // no signal for a refresh
        s.dark = true;
    }
  }

  InputFrame view(Stream& s) {
    if (s.dark) return {};
    if (!s.rgba) return InputFrame::of(s.frame);
    s.rgba_bytes.assign(std::size_t{kWidth} * kHeight * 4, 255);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        for (int k = 0; k < 3; ++k)
          s.rgba_bytes[(y * kWidth + x) * 4 + k] = s.frame.row(y)[x * 3 + k];
      }
    }
    return {s.rgba_bytes.data(), kWidth * 4, kWidth, kHeight, 4};
  }

  std::mt19937& rng_;
  EmulatorConfig config_;
  std::vector<Stream> streams_;
};

TEST(Prediction, RandomStreamsRouteAsIfEveryFrameWereParsed) {
  std::mt19937 rng(20261201);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  Router::PredictionCounts total;
  int walls = 0;
  for (; walls < 400 && (walls < 30 || std::chrono::steady_clock::now() < deadline); ++walls) {
    RandomWall wall(rng);
    SideBySide emu(wall.config());
    for (int t = 0; t < 24; ++t) {
      emu.tick(wall.next(), "wall " + std::to_string(walls) + " refresh " + std::to_string(t));
      if (::testing::Test::HasFatalFailure()) return;
    }
    total.predicted += emu.predictions().predicted;
    total.mispredicted += emu.predictions().mispredicted;
    total.checked_first += emu.predictions().checked_first;
    ASSERT_EQ(emu.parser_predictions().predicted, 0u);
  }
  // Every path was taken: predictions that held, that did not, checked while writing and
  // before writing.
  EXPECT_GT(total.predicted - total.mispredicted, 100u);
  EXPECT_GT(total.mispredicted, 20u);
  EXPECT_GT(total.checked_first, 20u);
  EXPECT_GT(total.predicted - total.checked_first, 100u);
}

}  // namespace
}  // namespace l2
