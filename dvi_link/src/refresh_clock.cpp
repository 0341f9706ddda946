#include "dvi_link/refresh_clock.hpp"

#include <fmt/format.h>
#include <stdexcept>
#include <thread>

namespace l2 {

RefreshClock::RefreshClock(double hz) : hz_(hz) {
  // Below 1 Hz the caller would sleep through seconds at a time (and a period of 1e-10 Hz
  // overflows); NaN fails every comparison.
  if (!(hz == 0.0 || (hz >= 1.0 && hz <= 1000.0))) {
    throw std::invalid_argument(
        fmt::format("refresh rate {} Hz is not 0 (as fast as possible) or 1..1000 Hz", hz));
  }
  if (hz > 0.0) {
    period_ = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
  }
  next_ = Clock::now() + period_;
}

void RefreshClock::wait_next() {
  if (hz_ == 0.0) return;
  const Clock::time_point now = Clock::now();
  if (now > next_ + period_) {
    const auto behind = (now - next_) / period_;  // whole periods missed
    missed_ += behind;
    next_ += behind * period_;
  }
  std::this_thread::sleep_until(next_);
  next_ += period_;
}

}  // namespace l2
