#include "run/stall_verdict.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(StallVerdict, ANamedLateProcessEndsTheRunAtTheTimeout) {
  EXPECT_FALSE(stall_ends_run(999, 1000, true));
  EXPECT_TRUE(stall_ends_run(1000, 1000, true));
}

// Under load every pipeserver delivered, the displays still had not swapped a second later, and
// the run ended saying "no pipeserver did not deliver frame 2": nobody hung.
TEST(StallVerdict, NobodyToNameWaitsTenTimesLongerButNotForever) {
  EXPECT_FALSE(stall_ends_run(1000, 1000, false));
  EXPECT_FALSE(stall_ends_run(9999, 1000, false));
  EXPECT_TRUE(stall_ends_run(10000, 1000, false));
}

}  // namespace
}  // namespace l2
