// Cursor frames to window commands on a 1000x500 canvas (the slop: 10 pixels): a drag, a
// pinch, a tap, two fingers on two windows, fingers that vanish, hostile spreads. Every place
// expected is worked out by hand from the fingers' pixels.
#include "touch/gestures.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

using Commands = std::vector<std::string>;

// Window 1 at 100,100 200x100; window 2 in front of it at 250,150 200x100.
const std::vector<WindowPlace> kWindows{{1, {100, 100, 200, 100}}, {2, {250, 150, 200, 100}}};

// Fingers in canvas pixels: (id, x, y) to 0..1.
CursorFrame frame(std::initializer_list<std::tuple<int, double, double>> fingers) {
  CursorFrame f;
  for (const auto& [id, x, y] : fingers) f.cursors.push_back({id, x / 1000.0, y / 500.0});
  return f;
}

TEST(Gestures, ADragMovesTheWindowOnceBeyondTheSlop) {
  Gestures g(1000, 500);
  EXPECT_EQ(g.take(frame({{1, 150, 150}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{1, 158, 150}}), kWindows), Commands{});  // within the slop
  EXPECT_EQ(g.take(frame({{1, 250, 200}}), kWindows), Commands{"move 1 200 150 200 100"});
  EXPECT_EQ(g.take(frame({{1, 250, 200}}), kWindows), Commands{});  // no new place
  EXPECT_EQ(g.take(frame({{1, 240, 230}}), kWindows), Commands{"move 1 190 180 200 100"});
  EXPECT_EQ(g.take(frame({}), kWindows), Commands{});  // lifted: no raise after a drag
  EXPECT_EQ(g.counts().drags, 1);
  EXPECT_EQ(g.counts().taps, 0);
  EXPECT_EQ(g.counts().moved, std::set<int>{1});
}

TEST(Gestures, ATapRaisesTheFrontWindowUnderTheFinger) {
  Gestures g(1000, 500);
  // 280,180 is in both windows: 2 is in front.
  EXPECT_EQ(g.take(frame({{3, 280, 180}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{3, 285, 184}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({}), kWindows), Commands{"raise 2"});
  // On the background: nothing.
  EXPECT_EQ(g.take(frame({{4, 900, 450}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({}), kWindows), Commands{});
  EXPECT_EQ(g.counts().taps, 1);
  EXPECT_EQ(g.counts().raised, 1);
  EXPECT_TRUE(g.counts().moved.empty());
}

TEST(Gestures, APinchScalesAboutItsCentre) {
  Gestures g(1000, 500);
  // 60 apart about 150,150; then 120 apart: twice the size, 150,150 staying where it is.
  g.take(frame({{1, 120, 150}}), kWindows);
  EXPECT_EQ(g.take(frame({{1, 120, 150}, {2, 180, 150}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{1, 90, 150}, {2, 210, 150}}), kWindows),
            Commands{"move 1 50 50 400 200"});
  // The centre moved by 20,10 at the same spread: the window follows it.
  EXPECT_EQ(g.take(frame({{1, 110, 160}, {2, 230, 160}}), kWindows),
            Commands{"move 1 70 60 400 200"});
  // One finger lifts: the other drags on from here, without a jump.
  EXPECT_EQ(g.take(frame({{2, 230, 160}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{2, 235, 160}}), kWindows), Commands{"move 1 75 60 400 200"});
  g.take(frame({}), kWindows);
  EXPECT_EQ(g.counts().pinches, 1);
  EXPECT_EQ(g.counts().drags, 0);
  EXPECT_EQ(g.counts().taps, 0);
}

TEST(Gestures, TwoFingersOnTwoWindowsDragEach) {
  Gestures g(1000, 500);
  EXPECT_EQ(g.take(frame({{1, 150, 120}, {2, 400, 200}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{1, 200, 120}, {2, 400, 240}}), kWindows),
            (Commands{"move 1 150 100 200 100", "move 2 250 190 200 100"}));
  g.take(frame({}), kWindows);
  EXPECT_EQ(g.counts().drags, 2);
  EXPECT_EQ(g.counts().moved, (std::set<int>{1, 2}));
}

TEST(Gestures, AFingerLandsOnAWindowWhereTheGestureMovedIt) {
  Gestures g(1000, 500);
  // Window 1 dragged right by 300 (to 400,100); the wall still shows it at 100,100.
  g.take(frame({{1, 150, 110}}), kWindows);
  ASSERT_EQ(g.take(frame({{1, 450, 110}}), kWindows), Commands{"move 1 400 100 200 100"});
  // A second finger at 550,120 is on the moved window: a pinch, not a tap on nothing.
  EXPECT_EQ(g.take(frame({{1, 450, 110}, {2, 550, 110}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{1, 400, 110}, {2, 600, 110}}), kWindows),
            Commands{"move 1 300 90 400 200"});
}

TEST(Gestures, FingersThatVanishEndTheirGesture) {
  Gestures g(1000, 500);
  g.take(frame({{1, 150, 150}}), kWindows);
  ASSERT_EQ(g.take(frame({{1, 200, 150}}), kWindows), Commands{"move 1 150 100 200 100"});
  // Its tracker lost it, and another finger is down elsewhere: the drag ended, nothing moves.
  EXPECT_EQ(g.take(frame({{9, 900, 450}}), kWindows), Commands{});
  EXPECT_EQ(g.take(frame({{9, 950, 480}}), kWindows), Commands{});
  EXPECT_EQ(g.counts().drags, 1);
}

TEST(Gestures, AThirdFingerIsIgnored) {
  Gestures g(1000, 500);
  g.take(frame({{1, 120, 150}, {2, 180, 150}, {3, 150, 120}}), kWindows);
  EXPECT_EQ(g.take(frame({{1, 120, 150}, {2, 180, 150}, {3, 290, 190}}), kWindows), Commands{});
}

TEST(Gestures, SpreadsBeyondAWindowsLimitsAreClamped) {
  Gestures g(1000, 500);
  g.take(frame({{1, 130, 140}, {2, 190, 140}}), kWindows);
  // Together at one point: as small as a window of that shape may be (2x1, a hundredth), about
  // it: 160 - 60/100, 140 - 40/100.
  EXPECT_EQ(g.take(frame({{1, 160, 140}, {2, 160, 140}}), kWindows),
            Commands{"move 1 159 140 2 1"});
  Gestures h(1000, 500);
  h.take(frame({{1, 149, 150}, {2, 151, 150}}), kWindows);
  // From 2 pixels apart to corner to corner (559 times): the sides stop at 16384 (81.92 times),
  // the centre from 150,150 to 500,250: 500 - 50 * 81.92, 250 - 50 * 81.92.
  EXPECT_EQ(h.take(frame({{1, 0, 0}, {2, 1000, 500}}), kWindows),
            Commands{"move 1 -3596 -3846 16384 8192"});
}

}  // namespace
}  // namespace l2
