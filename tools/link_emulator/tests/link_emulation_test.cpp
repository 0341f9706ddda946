// The link emulator's decisions against hand-written expectations: where a frame goes, how long
// it is held, and in which order held frames leave.
#include "link_emulation.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace l2::link_emulation {
namespace {

using std::chrono::milliseconds;

// An Ethernet frame from host `from` to host `to` (addresses 02:00:00:00:00:0N; 0xff: the
// broadcast address), its payload one byte.
std::vector<std::uint8_t> frame(int to, int from, std::uint8_t payload = 0) {
  std::vector<std::uint8_t> f(kEthernetHeader + 1, 0);
  for (int i = 0; i < 6; ++i) f[static_cast<std::size_t>(i)] = to == 0xff ? 0xff : 0;
  if (to != 0xff) f[0] = 0x02, f[5] = static_cast<std::uint8_t>(to);
  f[6] = 0x02;
  f[11] = static_cast<std::uint8_t>(from);
  f[12] = 0x08;  // IPv4
  f[kEthernetHeader] = payload;
  return f;
}

std::vector<int> ports(std::span<const int> out) {
  return {out.begin(), out.end()};
}

TEST(LearningSwitch, AnUnknownDestinationGoesToEveryOtherPortAKnownOneToItsPortAlone) {
  LearningSwitch sw(3);
  EXPECT_EQ(ports(sw.destinations(0, frame(2, 1))), (std::vector<int>{1, 2}));
  // Host 1 was seen on port 0: a frame to it from port 2 goes there only.
  EXPECT_EQ(ports(sw.destinations(2, frame(1, 2))), (std::vector<int>{0}));
  // And host 2 on port 2.
  EXPECT_EQ(ports(sw.destinations(0, frame(2, 1))), (std::vector<int>{2}));
}

TEST(LearningSwitch, BroadcastGoesEverywhereElseEvenFromAKnownHost) {
  LearningSwitch sw(4);
  sw.destinations(1, frame(0xff, 7));
  EXPECT_EQ(ports(sw.destinations(1, frame(0xff, 7))), (std::vector<int>{0, 2, 3}));
}

TEST(LearningSwitch, AFrameForAHostBehindItsOwnPortGoesNowhere) {
  LearningSwitch sw(2);
  sw.destinations(0, frame(0xff, 3));
  EXPECT_TRUE(sw.destinations(0, frame(3, 4)).empty());
}

TEST(LearningSwitch, AHostThatMovedIsFoundOnItsNewPort) {
  LearningSwitch sw(3);
  sw.destinations(0, frame(0xff, 5));
  sw.destinations(2, frame(0xff, 5));
  EXPECT_EQ(ports(sw.destinations(1, frame(5, 6))), (std::vector<int>{2}));
}

TEST(LearningSwitch, AFrameShorterThanAHeaderGoesNowhere) {
  LearningSwitch sw(3);
  const std::vector<std::uint8_t> runt(13, 0);
  EXPECT_TRUE(sw.destinations(0, runt).empty());
}

TEST(HoldFor, TheJitterSpansDelayMinusToPlusJitterAndNeverGoesBelowZero) {
  const LinkDelay link{milliseconds(5), milliseconds(5)};
  // random % (2 * 5e6 + 1) - 5e6 ns: 0 is the least, 2 * 5e6 the most.
  EXPECT_EQ(hold_for(link, 0), milliseconds(0));
  EXPECT_EQ(hold_for(link, 5000000), milliseconds(5));
  EXPECT_EQ(hold_for(link, 10000000), milliseconds(10));
  EXPECT_EQ(hold_for(link, 10000001), milliseconds(0));  // wraps
  const LinkDelay wide{milliseconds(1), milliseconds(3)};
  EXPECT_EQ(hold_for(wide, 0), milliseconds(0));  // 1 - 3 ms: held not at all
  EXPECT_EQ(hold_for(wide, 6000000), milliseconds(4));
  EXPECT_EQ(hold_for(LinkDelay{milliseconds(7), milliseconds(0)}, 12345), milliseconds(7));
}

// Releases what is due at `now`: the ports and payloads, in the order sent.
std::vector<std::pair<int, int>> release(HeldFrames& held, int now_ms) {
  std::vector<std::pair<int, int>> sent;
  held.release_due(milliseconds(now_ms), [&](int port, std::span<const std::uint8_t> bytes) {
    sent.emplace_back(port, bytes[kEthernetHeader]);
  });
  return sent;
}

TEST(HeldFrames, FramesLeaveAtTheirTimeEarliestFirstTiesInTheOrderHeld) {
  HeldFrames held(100);
  held.hold(milliseconds(0), milliseconds(9), 1, frame(1, 2, 10));
  held.hold(milliseconds(1), milliseconds(3), 2, frame(1, 2, 11));
  held.hold(milliseconds(2), milliseconds(3), 0, frame(1, 2, 12));
  held.hold(milliseconds(3), milliseconds(5), 1, frame(1, 2, 13));
  EXPECT_TRUE(release(held, 2).empty());
  EXPECT_EQ(release(held, 4), (std::vector<std::pair<int, int>>{{2, 11}, {0, 12}}));
  // The frame held second-to-last overtakes the first (jitter reorders, as netem's does).
  EXPECT_EQ(release(held, 9), (std::vector<std::pair<int, int>>{{1, 13}, {1, 10}}));
  EXPECT_TRUE(held.empty());
}

TEST(HeldFrames, CountsWhatItSentAndHowLongEachWasHeld) {
  HeldFrames held(10);
  held.hold(milliseconds(1), milliseconds(3), 0, frame(1, 2));
  held.hold(milliseconds(2), milliseconds(9), 0, frame(1, 2));
  release(held, 4);   // held 3 ms
  release(held, 12);  // held 10 ms
  const HeldCounts& c = held.counts();
  EXPECT_EQ(c.frames, 2u);
  EXPECT_EQ(c.bytes, 2u * (kEthernetHeader + 1));
  EXPECT_EQ(c.least, milliseconds(3));
  EXPECT_EQ(c.most, milliseconds(10));
  EXPECT_EQ(c.total, milliseconds(13));
}

TEST(HeldFrames, AFramePastTheLimitIsDroppedAndCounted) {
  HeldFrames held(2);
  EXPECT_TRUE(held.hold(milliseconds(0), milliseconds(5), 0, frame(1, 2, 1)));
  EXPECT_TRUE(held.hold(milliseconds(0), milliseconds(5), 0, frame(1, 2, 2)));
  EXPECT_FALSE(held.hold(milliseconds(0), milliseconds(5), 0, frame(1, 2, 3)));
  EXPECT_EQ(held.counts().over_limit, 1u);
  EXPECT_EQ(release(held, 5), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}}));
  // Room again once they left; a reused buffer carries the new frame's bytes.
  EXPECT_TRUE(held.hold(milliseconds(5), milliseconds(6), 1, frame(1, 2, 4)));
  EXPECT_EQ(release(held, 6), (std::vector<std::pair<int, int>>{{1, 4}}));
}

}  // namespace
}  // namespace l2::link_emulation
