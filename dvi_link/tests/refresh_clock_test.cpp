#include "dvi_link/refresh_clock.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

namespace l2 {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

TEST(RefreshClock, TicksAtTheConfiguredRate) {
  // Tick n of the clock is n periods after its construction. A caller descheduled by a loaded
  // machine comes back late and the clock skips the ticks it missed (counted): so 30 waits end
  // at tick 30 + missed, never before it and, with scheduling slack, not much after it. A clock
  // at half the rate would end at tick 60.
  const auto start = Clock::now();
  RefreshClock clock(100.0);
  for (int i = 0; i < 30; ++i) clock.wait_next();
  const auto took = Clock::now() - start;
  const auto last_tick = (30 + clock.missed()) * 10ms;
  EXPECT_GE(took, last_tick - 1ms);
  EXPECT_LT(took, last_tick + 10ms + 100ms);
}

TEST(RefreshClock, RateZeroNeverWaits) {
  const auto start = Clock::now();
  RefreshClock clock(0.0);
  for (int i = 0; i < 100000; ++i) clock.wait_next();
  EXPECT_LT(Clock::now() - start, 100ms);
}

TEST(RefreshClock, ALateCallerSkipsMissedTicksInsteadOfBursting) {
  RefreshClock clock(100.0);
  std::this_thread::sleep_for(55ms);  // five ticks late
  clock.wait_next();
  EXPECT_GE(clock.missed(), 4);
  // Without the skip, the next four waits would return at once to catch up.
  const auto start = Clock::now();
  for (int i = 0; i < 4; ++i) clock.wait_next();
  EXPECT_GE(Clock::now() - start, 25ms);
}

TEST(RefreshClock, RejectsRatesOutsideItsRange) {
  try {
    RefreshClock clock(-1.0);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "refresh rate -1 Hz is not 0 (as fast as possible) or 1..1000 Hz");
  }
  EXPECT_THROW(RefreshClock(5000.0), std::invalid_argument);
  // Below 1 Hz a caller slept through seconds; 1e-10 Hz overflowed the period; NaN passed.
  EXPECT_THROW(RefreshClock(0.5), std::invalid_argument);
  EXPECT_THROW(RefreshClock(1e-10), std::invalid_argument);
  EXPECT_THROW(RefreshClock(std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(RefreshClock(1.0));
}

}  // namespace
}  // namespace l2
