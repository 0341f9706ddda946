#include "balance/frame_load.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(FrameLoad, SlowestPipeserverAndItsRatioToTheMean) {
  const FrameLoad f = frame_load({{1, 2}, {1}, {0.5, 0.5, 1}});
  EXPECT_DOUBLE_EQ(f.frame_seconds, 3);
  EXPECT_DOUBLE_EQ(f.imbalance, 1.5);
}

TEST(FrameLoad, NothingMeasuredIsEven) {
  EXPECT_DOUBLE_EQ(frame_load({{0}, {0}}).imbalance, 1);
}

}  // namespace
}  // namespace l2
