// The pace at which the emulator takes in its DVI inputs: a fixed refresh rate (60 Hz by
// default, as a DVI link) or, with rate 0, as fast as possible.
#pragma once

#include <chrono>

namespace l2 {

inline constexpr double kDefaultRefreshHz = 60.0;

class RefreshClock {
 public:
  // hz 1..1000: ticks every 1/hz s; hz == 0: never waits. Throws std::invalid_argument
  // otherwise.
  explicit RefreshClock(double hz = kDefaultRefreshHz);

  // Sleeps until the next tick. Ticks are on a fixed grid from construction, so sleeping
  // inaccuracy does not accumulate; a caller that fell more than one period behind skips the
  // missed ticks instead of racing through them.
  void wait_next();
  // Ticks skipped because the caller was late.
  long long missed() const { return missed_; }
  double hz() const { return hz_; }

 private:
  using Clock = std::chrono::steady_clock;
  double hz_;
  Clock::duration period_{};
  Clock::time_point next_;
  long long missed_ = 0;
};

}  // namespace l2
