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
  std::vector<int> swapped;
  FrameSequencer::Decision decision;
  Script(int inputs, int groups) : seq(inputs, groups) {}
  void tick(std::vector<FrameObservation> frames) {
    seq.refresh(swapped);
    seq.decide(frames, decision);
    seq.commit(frames, decision);
  }
};

// Hosts as in a live run: host i needs period[i] refreshes to render a frame, starts rendering
// the next when it swaps one into its link, and swaps it in once it is rendered and READY for
// the last one has come; a frame swapped in is taken in at the next refresh. Every host's first
// frame is taken in at refresh 0.
class Hosts {
 public:
  Hosts(std::vector<int> period, std::vector<std::uint64_t> groups, int sequencer_groups)
      : script_(static_cast<int>(period.size()), sequencer_groups),
        period_(std::move(period)),
        groups_(std::move(groups)),
        frame_(period_.size(), 0),
        rendered_at_(period_),
        ready_(period_.size(), false) {}

  // One refresh.
  void tick() {
    std::vector<FrameObservation> frames;
    for (std::size_t i = 0; i < period_.size(); ++i) {
      if (ready_[i] && t_ >= rendered_at_[i]) {
        ++frame_[i];
        rendered_at_[i] = t_ + period_[i];
        ready_[i] = false;
      }
      frames.push_back(l2::frame(frame_[i] % 2, groups_[i]));
    }
    script_.tick(frames);
    for (const int i : script_.decision.ready_inputs) ready_[i] = true;
    ++t_;
  }
  const Script& script() const { return script_; }
  int frame(int host) const { return frame_[host]; }

 private:
  Script script_;
  std::vector<int> period_;
  std::vector<std::uint64_t> groups_;
  std::vector<int> frame_;  // the frame each host scans out
  std::vector<int> rendered_at_;
  std::vector<bool> ready_;
  int t_ = 0;
};

TEST(FrameSequencer, AHostThatIsAlwaysReadyGetsReadyAndANewFrameEveryRefresh) {
  Hosts hosts({1}, {1}, 1);
  for (int t = 0; t < 10; ++t) {
    hosts.tick();
    const Script& s = hosts.script();
    EXPECT_EQ(s.decision.kinds, std::vector<K>{K::New}) << "refresh " << t;
    EXPECT_EQ(s.decision.completed_groups, std::vector<int>{0}) << "refresh " << t;
    EXPECT_EQ(s.decision.ready_inputs, std::vector<int>{0}) << "refresh " << t;
    // Latency one frame: what completed at refresh t-1 swaps at refresh t.
    EXPECT_EQ(s.swapped, t == 0 ? std::vector<int>{} : std::vector<int>{0}) << "refresh " << t;
    EXPECT_EQ(hosts.frame(0), t);
  }
}

TEST(FrameSequencer, ASlowHostRunsAtItsOwnRate) {
  Hosts hosts({3}, {1}, 1);
  for (int t = 0; t < 12; ++t) {
    hosts.tick();
    const Script& s = hosts.script();
    const bool fresh = t % 3 == 0;  // taken in at 0; rendered in 3 refreshes from then on
    EXPECT_EQ(s.decision.kinds, std::vector<K>{fresh ? K::New : K::Repeat}) << "refresh " << t;
    EXPECT_EQ(s.decision.ready_inputs, fresh ? std::vector<int>{0} : std::vector<int>{})
        << "refresh " << t;
    EXPECT_EQ(s.swapped, t % 3 == 1 ? std::vector<int>{0} : std::vector<int>{}) << "refresh " << t;
    EXPECT_EQ(hosts.frame(0), t / 3);
  }
}

TEST(FrameSequencer, AFastHostInTheGroupOfASlowOneRunsAtTheSlowRate) {
  Hosts hosts({1, 2}, {1, 1}, 1);
  for (int t = 0; t < 8; ++t) {
    hosts.tick();
    const Script& s = hosts.script();
    // The fast host swaps its next frame in at READY and then waits for the slow one.
    const std::vector<K> kinds = t == 0       ? std::vector<K>{K::New, K::New}
                                 : t % 2 == 1 ? std::vector<K>{K::New, K::Repeat}
                                              : std::vector<K>{K::Repeat, K::New};
    EXPECT_EQ(s.decision.kinds, kinds) << "refresh " << t;
    EXPECT_EQ(s.decision.ready_inputs, t % 2 == 0 ? (std::vector<int>{0, 1}) : std::vector<int>{})
        << "refresh " << t;
  }
  EXPECT_EQ(hosts.frame(0), 4);
  EXPECT_EQ(hosts.frame(1), 3);
}

TEST(FrameSequencer, AHostWhoseFrameFedNoGroupOfTheRefreshIsNotWaitedFor) {
  // Host 0 (fast) feeds group 0; host 1 is slow and feeds group 1 only; host 2's frames feed no
  // group at all (only SKIPs, or displays the mesh lacks).
  Hosts hosts({1, 4, 1}, {0b01, 0b10, 0}, 2);
  for (int t = 0; t < 8; ++t) {
    hosts.tick();
    const Script& s = hosts.script();
    const bool slow_fresh = t % 4 == 0;
    EXPECT_EQ(s.decision.kinds, (std::vector<K>{K::New, slow_fresh ? K::New : K::Repeat, K::New}))
        << "refresh " << t;
    EXPECT_EQ(s.decision.completed_groups,
              slow_fresh ? (std::vector<int>{0, 1}) : std::vector<int>{0})
        << "refresh " << t;
    EXPECT_EQ(s.decision.ready_inputs,
              slow_fresh ? (std::vector<int>{0, 1, 2}) : (std::vector<int>{0, 2}))
        << "refresh " << t;
  }
  EXPECT_EQ(hosts.frame(0), 7);
  EXPECT_EQ(hosts.frame(1), 1);
  EXPECT_EQ(hosts.frame(2), 7);
}

TEST(FrameSequencer, AHostFeedingTwoGroupsGetsReadyWhenBothAreComplete) {
  // Host 0 feeds groups 0 and 1; host 1 feeds group 1 and needs 2 refreshes a frame. Group 0
  // has host 0's frame a refresh before group 1 does, and does not wait for host 1; host 0's
  // READY waits for both groups.
  Hosts hosts({1, 2}, {0b11, 0b10}, 2);
  for (int t = 0; t < 8; ++t) {
    hosts.tick();
    const Script& s = hosts.script();
    const std::string where = "refresh " + std::to_string(t);
    if (t == 0) {
      EXPECT_EQ(s.decision.kinds, (std::vector<K>{K::New, K::New}));
      EXPECT_EQ(s.decision.completed_groups, (std::vector<int>{0, 1}));
      EXPECT_EQ(s.decision.ready_inputs, (std::vector<int>{0, 1}));
    } else if (t % 2 == 1) {
      EXPECT_EQ(s.swapped, t == 1 ? (std::vector<int>{0, 1}) : std::vector<int>{1}) << where;
      EXPECT_EQ(s.decision.kinds, (std::vector<K>{K::New, K::Repeat})) << where;
      EXPECT_EQ(s.decision.completed_groups, std::vector<int>{0}) << where;
      EXPECT_TRUE(s.decision.ready_inputs.empty()) << where;
      EXPECT_TRUE(s.seq.awaiting_ready(0)) << where;
    } else {
      EXPECT_EQ(s.swapped, std::vector<int>{0}) << where;
      EXPECT_EQ(s.decision.kinds, (std::vector<K>{K::Repeat, K::New})) << where;
      EXPECT_EQ(s.decision.completed_groups, std::vector<int>{1}) << where;
      EXPECT_EQ(s.decision.ready_inputs, (std::vector<int>{0, 1})) << where;
    }
  }
  EXPECT_EQ(hosts.frame(0), 4);
  EXPECT_EQ(hosts.frame(1), 3);
}

TEST(FrameSequencer, ADecisionChangesNothingUntilItIsCommitted) {
  Script r(2, 1);
  r.tick({frame(0), frame(0)});
  // Asked about frames that turn out otherwise (a prediction, router.hpp), then about the real
  // ones: only the second counts.
  FrameSequencer::Decision wrong;
  r.seq.refresh(r.swapped);
  r.seq.decide(std::vector{frame(1), torn()}, wrong);
  EXPECT_EQ(wrong.kinds, (std::vector<K>{K::New, K::Torn}));
  EXPECT_TRUE(wrong.completed_groups.empty());
  const std::vector<FrameObservation> real{frame(1), frame(1)};
  r.seq.decide(real, r.decision);
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::New}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_EQ(r.decision.ready_inputs, (std::vector<int>{0, 1}));
  r.seq.commit(real, r.decision);
  EXPECT_FALSE(r.seq.awaiting_ready(0));
  r.tick({frame(0), frame(1)});
  EXPECT_EQ(r.swapped, std::vector<int>{0});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::Repeat}));
}

TEST(FrameSequencer, FirstFrameIsNewThenRepeatsUntilTheParityFlips) {
  Script r(1, 1);
  r.tick({frame(1)});  // the very first non-idle frame is new, whatever its parity
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_EQ(r.decision.route, std::vector<std::uint8_t>{1});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_EQ(r.decision.ready_inputs, std::vector<int>{0});  // at once, before the swap
  EXPECT_TRUE(r.swapped.empty());
  r.tick({frame(1)});  // swap at this refresh; same parity: repeat, not routed
  EXPECT_EQ(r.swapped, std::vector<int>{0});
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::Repeat});
  EXPECT_EQ(r.decision.route, std::vector<std::uint8_t>{0});
  EXPECT_TRUE(r.decision.completed_groups.empty());
  EXPECT_TRUE(r.decision.ready_inputs.empty());
  r.tick({frame(0)});
  EXPECT_TRUE(r.swapped.empty());
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_EQ(r.decision.ready_inputs, std::vector<int>{0});
}

TEST(FrameSequencer, GroupWaitsForEveryFeedingInput) {
  Script r(3, 1);
  r.tick({frame(0), frame(0), frame(0)});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_EQ(r.decision.ready_inputs, (std::vector<int>{0, 1, 2}));
  r.tick({frame(1), frame(0), frame(0)});  // input 0 is ahead; 1 and 2 repeat
  EXPECT_EQ(r.swapped, std::vector<int>{0});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::New, K::Repeat, K::Repeat}));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  EXPECT_TRUE(r.decision.ready_inputs.empty());
  r.tick({frame(1), frame(1), frame(0)});  // input 0 waits for READY: its frame repeats
  EXPECT_TRUE(r.swapped.empty());
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Repeat, K::New, K::Repeat}));
  EXPECT_TRUE(r.decision.completed_groups.empty());
  EXPECT_TRUE(r.decision.ready_inputs.empty());
  r.tick({frame(1), frame(1), frame(1)});
  EXPECT_EQ(r.decision.kinds, (std::vector<K>{K::Repeat, K::Repeat, K::New}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
  EXPECT_EQ(r.decision.ready_inputs, (std::vector<int>{0, 1, 2}));
  r.tick({frame(1), frame(1), frame(1)});
  EXPECT_EQ(r.swapped, std::vector<int>{0});
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
  EXPECT_EQ(r.swapped, (std::vector<int>{0, 1}));
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});  // group 1 does not wait
  EXPECT_EQ(r.decision.ready_inputs, std::vector<int>{0});
  r.tick({frame(0, 0b01), frame(0, 0b10)});
  EXPECT_EQ(r.swapped, std::vector<int>{0});
  EXPECT_EQ(r.decision.completed_groups, std::vector<int>{0});
}

TEST(FrameSequencer, AFrameFeedingNoGroupGetsReadyAtOnce) {
  Script r(1, 1);
  r.tick({frame(0, 0)});  // only SKIPs, or strips to displays the mesh lacks
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_TRUE(r.decision.completed_groups.empty());
  EXPECT_EQ(r.decision.ready_inputs, std::vector<int>{0});
  r.tick({frame(1, 0)});
  EXPECT_TRUE(r.swapped.empty());
  EXPECT_EQ(r.decision.kinds, std::vector<K>{K::New});
  EXPECT_EQ(r.decision.ready_inputs, std::vector<int>{0});
}

}  // namespace
}  // namespace l2
