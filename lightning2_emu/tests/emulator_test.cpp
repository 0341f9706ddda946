#include "lightning2_emu/emulator.hpp"

#include <gtest/gtest.h>

#include "lightning2_emu/frame_builder.hpp"

namespace l2 {
namespace {

using testing::FrameBuilder;
using K = FrameKind;

constexpr Rgb kBlack{};

Rgb colour(int input, int frame) {
  return {static_cast<std::uint8_t>(40 + input * 100), static_cast<std::uint8_t>(10 + frame * 20),
          static_cast<std::uint8_t>(frame)};
}

// A frame of `input` for application frame k: full rows y0..y1-1 of a display in one colour.
RgbImage rows_frame(int display, int width, int y0, int y1, Rgb c, bool parity) {
  FrameBuilder b(64, 8);
  for (int y = y0; y < y1; ++y) b.copy_fill(0, y - y0, display, 0, y, width, c, parity);
  return b.image();
}

// A frame whose COPY headers disagree on parity.
RgbImage torn_frame(int display, int width) {
  FrameBuilder b(64, 8);
  b.copy_fill(0, 0, display, 0, 0, width, Rgb{1, 1, 1}, false);
  b.copy_fill(0, 1, display, 0, 1, width, Rgb{1, 1, 1}, true);
  return b.image();
}

std::vector<InputFrame> views(const std::vector<RgbImage>& images) {
  std::vector<InputFrame> v;
  for (const RgbImage& i : images) v.push_back(i.empty() ? InputFrame{} : InputFrame::of(i));
  return v;
}

EmulatorConfig config(std::vector<DisplaySpec> displays, int workers = 2) {
  EmulatorConfig c;
  c.mesh = Mesh(1, 1, {64, 8});
  c.displays = std::move(displays);
  c.workers = workers;
  return c;
}

// Display 0 (16x4) fed by input 0 on rows 0-1 and input 1 on rows 2-3.
RgbImage expected_display(int frame) {
  RgbImage d(16, 4, kBlack);
  if (frame >= 0) {
    d.fill_rect(0, 0, 16, 2, colour(0, frame));
    d.fill_rect(0, 2, 16, 2, colour(1, frame));
  }
  return d;
}

TEST(Emulator, DisplayShowsFrameKMinusOneWhileFrameKIsDelivered) {
  Emulator emu(config({{0, 16, 4, 0}}));
  for (int k = 0; k < 5; ++k) {
    const std::vector<RgbImage> frames = {rows_frame(0, 16, 0, 2, colour(0, k), k % 2),
                                          rows_frame(0, 16, 2, 4, colour(1, k), k % 2)};
    const Emulator::Tick& t = emu.tick(views(frames));
    EXPECT_EQ(t.kinds, (std::vector<K>{K::New, K::New, K::NoSignal, K::NoSignal}));
    EXPECT_EQ(emu.shown(0), expected_display(k - 1)) << "while frame " << k << " is delivered";
    EXPECT_EQ(t.completed_groups, std::vector<int>{0});
    // READY in the refresh the frame completes, so the hosts' next frames come at the next.
    EXPECT_EQ(t.ready_inputs, (std::vector<int>{0, 1}));
    if (k > 0) {
      EXPECT_EQ(t.swapped_groups, std::vector<int>{0});
    }
  }
  emu.tick({});  // no signal: the last frame still reaches the display
  EXPECT_EQ(emu.shown(0), expected_display(4));
  EXPECT_EQ(emu.report().groups[0].swaps, 5u);
  EXPECT_EQ(emu.report().displays[0].frames, 5u);
  EXPECT_EQ(emu.report().displays[0].covered_pixels, 5u * 64u);
}

TEST(Emulator, TornAndRepeatedFramesLeaveTheDisplayAlone) {
  Emulator emu(config({{0, 16, 4, 0}}));
  auto frame = [](int input, int k) {
    return rows_frame(0, 16, 2 * input, 2 * input + 2, colour(input, k), k % 2);
  };
  emu.tick(views({frame(0, 0), frame(1, 0)}));
  const Emulator::Tick& t1 = emu.tick(views({frame(0, 1), torn_frame(0, 16)}));
  EXPECT_EQ(t1.kinds[1], K::Torn);
  EXPECT_TRUE(t1.completed_groups.empty());
  EXPECT_EQ(emu.shown(0), expected_display(0));
  const Emulator::Tick& t2 = emu.tick(views({frame(0, 1), frame(1, 0)}));  // 1 still on 0
  EXPECT_EQ(t2.kinds, (std::vector<K>{K::Repeat, K::Repeat, K::NoSignal, K::NoSignal}));
  EXPECT_EQ(emu.shown(0), expected_display(0));
  emu.tick(views({frame(0, 1), frame(1, 1)}));
  EXPECT_EQ(emu.shown(0), expected_display(0));
  emu.tick(views({frame(0, 1), frame(1, 1)}));
  EXPECT_EQ(emu.shown(0), expected_display(1));
  EXPECT_EQ(emu.report().frames(K::Torn), 1u);
  EXPECT_EQ(emu.report().frames(K::Repeat), 5u);
  EXPECT_EQ(emu.report().groups[0].swaps, 2u);
}

TEST(Emulator, IdleInputsHoldUpNothing) {
  Emulator emu(config({{0, 16, 4, 0}}));
  const RgbImage black(64, 8);  // every scanline reads as END
  emu.tick(views({rows_frame(0, 16, 0, 2, colour(0, 0), false), black}));
  const Emulator::Tick& t = emu.tick(views({rows_frame(0, 16, 0, 2, colour(0, 0), false), black}));
  EXPECT_EQ(t.kinds[1], K::Idle);
  RgbImage expected(16, 4, kBlack);
  expected.fill_rect(0, 0, 16, 2, colour(0, 0));
  EXPECT_EQ(emu.shown(0), expected);
  EXPECT_EQ(emu.report().frames(K::Idle), 2u);
}

// Input 1 delivers a refresh before input 0, over the same pixels: input 1 still wins (§5),
// and input 0's pixels elsewhere are written.
TEST(Emulator, PriorityHoldsWhenInputsDeliverAtDifferentRefreshes) {
  Emulator emu(config({{0, 16, 4, 0}}));
  const Rgb red{200, 0, 0}, green{0, 200, 0};
  const RgbImage in1 = rows_frame(0, 16, 1, 3, green, false);
  const RgbImage in0 = rows_frame(0, 16, 0, 4, red, false);
  const Emulator::Tick& t0 = emu.tick(views({torn_frame(0, 16), in1}));
  EXPECT_EQ(t0.kinds[0], K::Torn);
  EXPECT_EQ(t0.kinds[1], K::New);
  EXPECT_TRUE(t0.completed_groups.empty());
  const Emulator::Tick& t1 = emu.tick(views({in0, in1}));
  EXPECT_EQ(t1.kinds[0], K::New);
  EXPECT_EQ(t1.kinds[1], K::Repeat);
  ASSERT_EQ(t1.completed.size(), 1u);
  EXPECT_EQ(t1.completed[0].strips, 6u);
  EXPECT_EQ(t1.completed[0].covered_pixels, 64u);
  EXPECT_EQ(t1.completed[0].overdraw_pixels, 32u);
  emu.tick(views({in0, in1}));
  RgbImage expected(16, 4, red);
  expected.fill_rect(0, 1, 16, 2, green);
  EXPECT_EQ(emu.shown(0), expected);
}

TEST(Emulator, SwapLockGroupsSwapTheirOwnDisplaysTogether) {
  // Displays 0 and 1 in group 7, fed by input 0; display 2 in group 3, fed by input 1.
  Emulator emu(config({{0, 16, 4, 7}, {1, 16, 4, 7}, {2, 16, 4, 3}}));
  auto frame01 = [](int k) {
    FrameBuilder b(64, 8);
    b.copy_fill(0, 0, 0, 0, 0, 16, colour(0, k), k % 2);
    b.copy_fill(0, 1, 1, 0, 0, 16, colour(0, k), k % 2);
    return b.image();
  };
  auto frame2 = [](int k) { return rows_frame(2, 16, 0, 1, colour(1, k), k % 2); };
  auto shows = [&](int display, Rgb c) { return emu.shown(display).at(5, 0) == c; };
  emu.tick(views({frame01(0), frame2(0)}));
  emu.tick(views({frame01(1), frame2(0)}));  // input 1 lags: group 3 has nothing new
  EXPECT_TRUE(shows(0, colour(0, 0)));
  EXPECT_TRUE(shows(1, colour(0, 0)));
  EXPECT_TRUE(shows(2, colour(1, 0)));
  const Emulator::Tick& t = emu.tick(views({frame01(2), frame2(0)}));
  EXPECT_EQ(t.swapped_groups, std::vector<int>{7});
  EXPECT_TRUE(shows(0, colour(0, 1)));
  EXPECT_TRUE(shows(1, colour(0, 1)));
  EXPECT_TRUE(shows(2, colour(1, 0)));
  emu.tick(views({frame01(2), frame2(1)}));
  const Emulator::Tick& t4 = emu.tick(views({frame01(3), frame2(1)}));
  EXPECT_EQ(t4.swapped_groups, std::vector<int>{3});
  EXPECT_TRUE(shows(0, colour(0, 2)));
  EXPECT_TRUE(shows(2, colour(1, 1)));
  ASSERT_EQ(emu.groups().size(), 2u);
  EXPECT_EQ(emu.groups()[0].id, 3);
  EXPECT_EQ(emu.groups()[0].swaps, 2u);
  EXPECT_EQ(emu.groups()[1].id, 7);
  EXPECT_EQ(emu.groups()[1].swaps, 3u);
}

TEST(Emulator, SerialAndParallelRunsAreIdentical) {
  std::vector<std::vector<RgbImage>> script;
  for (int k = 0; k < 6; ++k) {
    script.push_back({rows_frame(0, 16, 0, 3, colour(0, k), k % 2),
                      k == 2 ? torn_frame(0, 16) : rows_frame(0, 12, 1, 4, colour(1, k), k % 2),
                      rows_frame(1, 8, 0, 2, colour(2, k), (k / 2) % 2)});
  }
  std::vector<std::vector<RgbImage>> shown[2];
  for (int run = 0; run < 2; ++run) {
    Emulator emu(config({{0, 16, 4, 0}, {1, 8, 2, 0}}, run == 0 ? 1 : 3));
    for (const auto& frames : script) {
      emu.tick(views(frames));
      shown[run].push_back({emu.shown(0), emu.shown(1)});
    }
  }
  EXPECT_EQ(shown[0], shown[1]);
}

}  // namespace
}  // namespace l2
