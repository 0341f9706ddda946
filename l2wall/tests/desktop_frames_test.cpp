#include "desktops/desktop_frames.hpp"

#include <gtest/gtest.h>

#include "balance/desktop_messages.hpp"

namespace l2 {
namespace {

// The desktop a pipeserver holds after the lines it was sent, painted into a picture of the
// desktop's size (black where it holds nothing).
void apply(const std::vector<std::string>& lines, RgbImage& held) {
  const DesktopMessage m = decode_desktop(lines.at(0));
  ASSERT_EQ(static_cast<std::size_t>(m.rects) + 1, lines.size());
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const DesktopRect r = decode_desktop_rect(lines[i]);
    for (int y = 0; y < r.rect.h; ++y)
      std::copy_n(r.rgb.data() + y * r.rect.w * 3, r.rect.w * 3,
                  held.row(r.rect.y + y).data() + r.rect.x * 3);
  }
}

TEST(DesktopFrames, FirstFrameSendsEachPipeserverOnlyItsTilesWhole) {
  DesktopFrames d(40, 20, 2);
  d.live().fill({1, 2, 3});
  d.damaged({0, 0, 40, 20});
  const std::vector<std::string> a = d.answer(0, 0, {{0, 0, 20, 20}});
  const std::vector<std::string> b = d.answer(1, 0, {{20, 0, 30, 20}});  // past the desktop
  EXPECT_EQ(a[0], "DESKTOP 0 40 20 1 0 0 20 20 1");
  EXPECT_EQ(b[0], "DESKTOP 0 40 20 1 20 0 20 20 1");  // clipped to the desktop
  RgbImage held(40, 20);
  apply(b, held);
  EXPECT_EQ(held.at(20, 0), (Rgb{1, 2, 3}));
  EXPECT_EQ(held.at(39, 19), (Rgb{1, 2, 3}));
  EXPECT_EQ(held.at(19, 0), (Rgb{0, 0, 0}));  // not its tile: never sent
}

TEST(DesktopFrames, EveryPipeserverGetsTheFrozenStateNotTheLiveOne) {
  DesktopFrames d(40, 20, 2);
  d.live().fill({9, 9, 9});
  d.answer(0, 0, {{0, 0, 20, 20}});
  d.answer(1, 0, {{20, 0, 20, 20}});
  // Frame 1 is frozen when pipeserver 0 asks; the desktop changes again before pipeserver 1
  // asks: it must still be sent frame 1's state.
  d.live().fill({50, 0, 0});
  d.damaged({0, 0, 40, 20});
  const auto a = d.answer(0, 1, {{0, 0, 20, 20}});
  d.live().fill({0, 60, 0});
  d.damaged({0, 0, 40, 20});
  const auto b = d.answer(1, 1, {{20, 0, 20, 20}});
  RgbImage held(40, 20);
  apply(a, held);
  apply(b, held);
  EXPECT_EQ(held.at(5, 5), (Rgb{50, 0, 0}));
  EXPECT_EQ(held.at(25, 5), (Rgb{50, 0, 0}));
  // And frame 2 carries the change after it.
  const auto c = d.answer(1, 2, {{20, 0, 20, 20}});
  apply(c, held);
  EXPECT_EQ(held.at(25, 5), (Rgb{0, 60, 0}));
}

TEST(DesktopFrames, OnlyWhatChangedInsideItsTilesIsSent) {
  DesktopFrames d(40, 20, 2);
  d.answer(0, 0, {{0, 0, 20, 20}});
  d.answer(1, 0, {{20, 0, 20, 20}});
  d.live().fill_rect(18, 2, 4, 3, {7, 7, 7});
  d.damaged({18, 2, 4, 3});
  const auto a = d.answer(0, 1, {{0, 0, 20, 20}});
  const auto b = d.answer(1, 1, {{20, 0, 20, 20}});
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(decode_desktop_rect(a[1]).rect, (Rect{18, 2, 2, 3}));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(decode_desktop_rect(b[1]).rect, (Rect{20, 2, 2, 3}));
  // Nothing changed: headers alone.
  EXPECT_EQ(d.answer(0, 2, {{0, 0, 20, 20}}),
            std::vector<std::string>{"DESKTOP 2 40 20 1 0 0 20 20 0"});
}

TEST(DesktopFrames, FramesOutOfTurnAreRefused) {
  DesktopFrames d(8, 8, 2);
  d.answer(0, 0, {{0, 0, 8, 8}});
  EXPECT_THROW(d.answer(0, 0, {{0, 0, 8, 8}}), DesktopError);  // the same frame twice
  EXPECT_THROW(d.answer(1, 2, {{0, 0, 8, 8}}), DesktopError);  // two ahead of the last frozen
  EXPECT_THROW(d.answer(2, 1, {{0, 0, 8, 8}}), DesktopError);  // no such pipeserver
}

TEST(DesktopFrames, KeepsOnlyTheFramesSomePipeserverStillNeeds) {
  DesktopFrames d(8, 8, 2);
  for (int k = 0; k < 10; ++k) {
    d.answer(0, k, {{0, 0, 4, 8}});
    d.answer(1, k, {{4, 0, 4, 8}});
    EXPECT_EQ(d.kept(), 1u);
  }
  for (int k = 10; k < 20; ++k) d.answer(0, k, {{0, 0, 4, 8}});  // pipeserver 1 stopped asking
  EXPECT_LE(d.kept(), 4u);
  // Should it ask again, it is sent its region whole.
  const auto late = d.answer(1, 19, {{4, 0, 4, 8}});
  EXPECT_EQ(late.size(), 2u);
  EXPECT_EQ(decode_desktop_rect(late[1]).rect, (Rect{4, 0, 4, 8}));
}

}  // namespace
}  // namespace l2
