#include "lightning2_emu/frame_sequencer.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

using K = FrameKind;

FrameObservation frame(int parity, std::uint64_t groups = 1) {
  return {true, false, false, parity, groups};
}
FrameObservation idle() {
  return {true, true, false, 0, 0};
}
FrameObservation torn(std::uint64_t groups = 1) {
  return {true, false, true, 0, groups};
}

// Drives a sequencer one refresh at a time and keeps the last results.
struct Script {
  FrameSequencer seq;
  FrameSequencer::Refresh refresh;
  FrameSequencer::Decision decision;
  Script(int inputs, int groups) : seq(inputs, groups) {}
  void tick(std::vector<FrameObservation> frames) {
    seq.refresh(refresh);
    seq.observe(frames, decision);
  }
};

TEST(FrameSequencer, FirstFrameIsNewThenRepeatsUntilTheParityFlips) {
  Script r(1, 1);
  r.tick({frame(1)});  // the very first non-idle frame is new, whatever its parity
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_EQ(r.decision.route, std::vector<std::uint8_t>{1});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_TRUE(r.refresh.swapped_groups.empty());
  r.tick({frame(1)});  // swap at this refresh, READY out; same parity: repeat, not routed
  EXPECT_EQ(r.refresh.swapped_groups, std::vector<int>{0});
  EXPECT_EQ(r.refresh.ready_inputs, std::vector<int>{0});
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::Repeat});
  EXPECT_EQ(r.decision.route, std::vector<std::uint8_t>{0});
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(0)});
  EXPECT_TRUE(r.refresh.swapped_groups.empty());
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
}

TEST(FrameSequencer, GroupWaitsForEveryFeedingInput) {
  Script r(3, 1);
  r.tick({frame(0), frame(0), frame(0)});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  r.tick({frame(1), frame(0), frame(0)});  // input 0 is ahead; 1 and 2 repeat
  EXPECT_EQ(r.refresh.ready_inputs, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::Repeat, K::Repeat}));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(1), frame(1), frame(0)});  // input 0 waits for READY: its frame repeats
  EXPECT_TRUE(r.refresh.swapped_groups.empty());
  EXPECT_TRUE(r.refresh.ready_inputs.empty());
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Repeat, K::New, K::Repeat}));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(1), frame(1), frame(1)});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Repeat, K::Repeat, K::New}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  r.tick({frame(1), frame(1), frame(1)});
  EXPECT_EQ(r.refresh.swapped_groups, std::vector<int>{0});
  EXPECT_EQ(r.refresh.ready_inputs, (std::vector<int>{0, 1, 2}));
}

TEST(FrameSequencer, TornFramesAreDiscardedAndHoldTheGroup) {
  Script r(2, 1);
  r.tick({frame(0), frame(0)});
  r.tick({frame(1), torn()});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::Torn}));
  EXPECT_EQ(r.decision.route, (std::vector<std::uint8_t>{1, 0}));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(1), frame(1)});  // the torn frame's parity was never accepted
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Repeat, K::New}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
}

TEST(FrameSequencer, IdleAndSilentInputsHoldUpNothing) {
  Script r(3, 1);
  r.tick({frame(0), idle(), FrameObservation{}});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::Idle, K::NoSignal}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  r.tick({frame(1), frame(0), idle()});  // input 1 starts: its first frame is new
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::New, K::Idle}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  r.tick({});  // fewer observations than inputs: no signal
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::NoSignal, K::NoSignal, K::NoSignal}));
}

TEST(FrameSequencer, AHostThatDoesNotWaitForReadyIsEarly) {
  Script r(2, 1);
  r.tick({frame(0), frame(0)});
  r.tick({frame(1), frame(0)});
  r.tick({frame(0), frame(0)});  // input 0 flips again without READY
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Early, K::Repeat}));
  EXPECT_EQ(r.decision.route, (std::vector<std::uint8_t>{0, 0}));
  EXPECT_TRUE(r.seq.awaiting_ready(0));
}

TEST(FrameSequencer, GroupsSwapIndependently) {
  Script r(2, 2);
  // Input 0 feeds group 0, input 1 feeds group 1.
  r.tick({frame(0, 0b01), frame(0, 0b10)});
  EXPECT_EQ(r.decision.completed_groups, (std::vector<int>{0, 1}));
  r.tick({frame(1, 0b01), frame(0, 0b10)});
  EXPECT_EQ(r.refresh.swapped_groups, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});  // group 1 does not wait
  r.tick({frame(1, 0b01), frame(0, 0b10)});
  EXPECT_EQ(r.refresh.swapped_groups, std::vector<int>{0});
  EXPECT_EQ(r.refresh.ready_inputs, std::vector<int>{0});
}

TEST(FrameSequencer, ReadyWaitsForEveryGroupTheFrameFed) {
  Script r(2, 2);
  // Input 0 feeds both groups; input 1 feeds group 1 only and lags.
  r.tick({frame(0, 0b11), frame(0, 0b10)});
  EXPECT_EQ(r.decision.completed_groups, (std::vector<int>{0, 1}));
  r.tick({frame(1, 0b11), frame(0, 0b10)});
  EXPECT_EQ(r.refresh.ready_inputs, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});  // group 1 waits for input 1
  r.tick({frame(1, 0b11), frame(0, 0b10)});
  EXPECT_EQ(r.refresh.swapped_groups, std::vector<int>{0});
  EXPECT_TRUE(r.refresh.ready_inputs.empty());  // its frame is not shown on group 1 yet
  EXPECT_TRUE(r.seq.awaiting_ready(0));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(1, 0b11), frame(1, 0b10)});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{1});
  r.tick({frame(1, 0b11), frame(1, 0b10)});
  EXPECT_EQ(r.refresh.swapped_groups, std::vector<int>{1});
  EXPECT_EQ(r.refresh.ready_inputs, (std::vector<int>{0, 1}));
}

TEST(FrameSequencer, AFrameFeedingNoGroupGetsReadyAtTheNextRefresh) {
  Script r(1, 1);
  r.tick({frame(0, 0)});  // only SKIPs, or strips to displays the mesh lacks
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_TRUE(r.decision.completed_groups.empty());
  r.tick({frame(0, 0)});
  EXPECT_EQ(r.refresh.ready_inputs, std::vector<int>{0});
  EXPECT_TRUE(r.refresh.swapped_groups.empty());
}

}  // namespace
}  // namespace l2
