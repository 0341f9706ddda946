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
  // at tick 30 + missed, never before it. How long after it the caller runs again is the
  // scheduler's, so the upper bound is the clock's own count, not a slack: one more wait counts
  // every tick missed until it began, so it began before tick 32 + missed (the tick after the
  // one it returns at), and `end` was read before it began. A clock at half the rate ends the
  // 30 waits at tick 60, having missed none.
  const auto start = Clock::now();
  RefreshClock clock(100.0);
  const auto built = Clock::now();
  for (int i = 0; i < 30; ++i) clock.wait_next();
  const auto end = Clock::now();
  const auto last_tick = (30 + clock.missed()) * 10ms;
  EXPECT_GE(end - start, last_tick - 1ms);
  clock.wait_next();
  EXPECT_LT(end - built, (32 + clock.missed()) * 10ms);
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
