// The one viz path driven over in-memory compositors: frame k is composed once the test says so.
// The path's swaps, pictures and the late line of compositors that bound a frame's time are
// checked against what the test composed.
#include <gtest/gtest.h>

#include "l2wall/run_fault.hpp"
#include "l2wall/viz_path.hpp"

namespace l2 {
namespace {

class FakeCompositors final : public Compositors {
 public:
  bool composed(int frame, std::chrono::milliseconds) override {
    ++asked;
    if (asked >= compose_after) done = std::max(done, frame);
    return frame <= done;
  }
  DisplayPictures pictures(int frame) override {
    picture = RgbImage(1, 1);
    picture.data()[0] = static_cast<std::uint8_t>(frame);
    shown_ = frame;
    return [this](int) -> const RgbImage& { return picture; };
  }
  std::optional<DisplayPictures> shown() const override { return std::nullopt; }
  int frame_shown() const override { return shown_; }
  std::optional<std::chrono::milliseconds> frame_limit() const override { return limit; }
  std::string late(int frame) const override { return "frame " + std::to_string(frame) + " late"; }

  int asked = 0, compose_after = 3, done = -1, shown_ = -1;
  std::optional<std::chrono::milliseconds> limit;
  RgbImage picture;
};

struct Watched {
  int processes = 0, waiting = 0;
  RunWatch watch{[this] { ++processes; }, [this] { ++waiting; }};
};

TEST(VizPath, StepsOnceTheFrameIsComposedWatchingTheRunMeanwhile) {
  auto owned = std::make_unique<FakeCompositors>();
  FakeCompositors& c = *owned;
  VizPath path(std::move(owned));
  PipeserverSet none;
  std::vector<FrameRecord> records(2);
  Watched w;
  const auto swap = path.step(0, none, records, w.watch);
  ASSERT_TRUE(swap);
  EXPECT_EQ(swap->lowest, 0);
  EXPECT_FALSE(swap->refresh);  // no refresh on this path
  EXPECT_EQ(c.asked, 3);
  EXPECT_EQ(w.waiting, 2);  // the run's stall check, between the asks
  EXPECT_EQ(path.frame_pictures(0, w.watch)(0).data()[0], 0);
  EXPECT_EQ(path.frame_shown(), 0);
}

TEST(VizPath, CompositorsThatBoundAFrameAreNamedLate) {
  auto owned = std::make_unique<FakeCompositors>();
  owned->compose_after = 1 << 30;
  owned->limit = std::chrono::milliseconds(30);
  VizPath path(std::move(owned));
  Watched w;
  try {
    path.take_frame(4, w.watch);
    FAIL() << "not late";
  } catch (const RunFault& e) {
    EXPECT_STREQ(e.what(), "frame 4 late");
  }
  EXPECT_GT(w.processes, 0);
  EXPECT_EQ(w.waiting, 0);  // their own bound, not the run's stall check
}

}  // namespace
}  // namespace l2
