// TUIO 1.1 cursor messages to committed frames: the frame comes at fseq, alive says who is down,
// set says where; every hostile value is dropped, counted, and changes nothing.
#include "touch/tuio_cursors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "osc_messages.hpp"

namespace l2 {
namespace {

using namespace testing_support;

std::optional<CursorFrame> feed(TuioCursors& c, const std::vector<OscMessage>& messages) {
  std::optional<CursorFrame> last;
  for (const OscMessage& m : messages) {
    if (auto f = c.take(m)) last = f;
  }
  return last;
}

TEST(TuioCursors, AFrameIsCommittedAtFseq) {
  TuioCursors c;
  EXPECT_FALSE(c.take(alive({4})));
  EXPECT_FALSE(c.take(set(4, 0.25, 0.5)));
  const auto f = c.take(fseq(1));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->fseq, 1);
  EXPECT_EQ(f->cursors, (std::vector<Cursor>{{4, 0.25, 0.5}}));
  // Still down, not moved: alive without set keeps its place.
  const auto still = feed(c, {alive({4}), fseq(2)});
  ASSERT_TRUE(still);
  EXPECT_EQ(still->cursors, (std::vector<Cursor>{{4, 0.25, 0.5}}));
  // Lifted: no longer alive.
  const auto lifted = feed(c, {alive({}), fseq(3)});
  ASSERT_TRUE(lifted);
  EXPECT_TRUE(lifted->cursors.empty());
  EXPECT_EQ(c.dropped_messages(), 0);
}

TEST(TuioCursors, FingersAreInIdOrderAndOnlyAliveOnesWithAPlace) {
  TuioCursors c;
  // 9 alive but never set; 5 set but not alive; 2 set twice: the last set counts.
  const auto f = feed(c, {alive({7, 2, 9, 7}), set(7, 0.1, 0.2), set(2, 0.3, 0.4), set(2, 0.5, 0.6),
                          set(5, 0.7, 0.8), fseq(10)});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->cursors, (std::vector<Cursor>{{2, 0.5, 0.6}, {7, 0.1, 0.2}}));
  // Vanished without a word: 7 is no longer in alive, 9 gets its place now.
  const auto next = feed(c, {alive({2, 9}), set(9, 1.0, 0.0), fseq(11)});
  ASSERT_TRUE(next);
  EXPECT_EQ(next->cursors, (std::vector<Cursor>{{2, 0.5, 0.6}, {9, 1.0, 0.0}}));
}

TEST(TuioCursors, ALateFrameIsDroppedWithItsMessages) {
  TuioCursors c;
  ASSERT_TRUE(feed(c, {alive({1}), set(1, 0.5, 0.5), fseq(500)}));
  EXPECT_FALSE(feed(c, {alive({1}), set(1, 0.9, 0.9), fseq(499)}));
  EXPECT_FALSE(feed(c, {alive({1}), set(1, 0.9, 0.9), fseq(500)}));
  EXPECT_EQ(c.dropped_messages(), 2);
  const auto f = feed(c, {fseq(501)});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->cursors, (std::vector<Cursor>{{1, 0.5, 0.5}}));
  // Far behind: a tracker that started again. -1: a tracker that does not number frames.
  ASSERT_TRUE(feed(c, {set(1, 0.25, 0.25), fseq(0)}));
  const auto unnumbered = feed(c, {set(1, 0.75, 0.75), fseq(-1)});
  ASSERT_TRUE(unnumbered);
  EXPECT_EQ(unnumbered->cursors, (std::vector<Cursor>{{1, 0.75, 0.75}}));
  EXPECT_EQ(c.dropped_messages(), 2);
}

TEST(TuioCursors, HostileValuesAreDroppedAndCounted) {
  TuioCursors c;
  ASSERT_TRUE(feed(c, {alive({1}), set(1, 0.5, 0.5), fseq(1)}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<int> too_many(kMaxTouchCursors + 1);
  for (int k = 0; k <= kMaxTouchCursors; ++k) too_many[static_cast<std::size_t>(k)] = k;
  const std::vector<OscMessage> hostile{
      set(1, nan, 0.5),                                               // NaN
      set(1, 0.5, inf),                                               // infinity
      set(1, -0.01, 0.5),                                             // out of range
      set(1, 0.5, 1.5),                                               // out of range
      set(-3, 0.5, 0.5),                                              // a negative id
      cur({s("set"), i(1), i(0), f(0.5)}),                            // x an int
      cur({s("set"), i(1, 'h'), f(0.5), f(0.5)}),                     // a 64-bit id
      cur({s("set"), i(1), f(0.5)}),                                  // no y
      cur({s("set"), i(1), f(0.5), f(0.5), f(0), f(0), f(0), f(0)}),  // too many numbers
      cur({s("set"), i(1), f(0.5), f(0.5), s("fast")}),               // a word for a number
      alive(too_many),                                                // more fingers than kept
      cur({s("alive"), i(1), s("2")}),                                // a word for an id
      cur({s("fseq"), f(2)}),                                         // a frame number not int32
      cur({s("fseq")}),                                               // no frame number
      cur({s("touch"), i(1)}),                                        // no such command
      cur({}),                                                        // no command at all
      cur({i(5)}),                                                    // a number for a command
  };
  for (const OscMessage& m : hostile) EXPECT_FALSE(c.take(m));
  EXPECT_EQ(c.dropped_messages(), 17);
  const auto f = c.take(fseq(2));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->cursors, (std::vector<Cursor>{{1, 0.5, 0.5}}));
  // The edges of the range are in it.
  const auto edges = feed(c, {alive({0}), set(0, 0.0, 1.0), fseq(3)});
  ASSERT_TRUE(edges);
  EXPECT_EQ(edges->cursors, (std::vector<Cursor>{{0, 0.0, 1.0}}));
  EXPECT_EQ(c.dropped_messages(), 17);
}

TEST(TuioCursors, SetsOfAFrameAreBounded) {
  TuioCursors c;
  // Sets of ids not alive still take room until the frame ends: the 33rd is dropped.
  for (int id = 0; id <= kMaxTouchCursors; ++id) c.take(set(100 + id, 0.5, 0.5));
  EXPECT_EQ(c.dropped_messages(), 1);
  const auto f = feed(c, {alive({100}), fseq(1)});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->cursors, (std::vector<Cursor>{{100, 0.5, 0.5}}));
}

TEST(TuioCursors, OtherProfilesAndSourceAreNotCursors) {
  TuioCursors c;
  EXPECT_FALSE(c.take({"/tuio/2Dobj", {s("set"), i(1), i(2), f(0.5), f(0.5), f(0)}}));
  EXPECT_FALSE(c.take({"/tuio/2Dcur", {s("source"), s("wall@10.0.0.2")}}));
  EXPECT_FALSE(c.take({"/tuio/2Dobj", {s("fseq"), i(1)}}));
  EXPECT_EQ(c.dropped_messages(), 0);
}

}  // namespace
}  // namespace l2
