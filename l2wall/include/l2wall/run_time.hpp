// Time in the live run: one clock, milliseconds between two points, and the time spent writing
// saved pictures (PNG writing is not part of the frame rate, so it is measured and taken out).
#pragma once

#include <chrono>

namespace l2 {

using RunClock = std::chrono::steady_clock;

inline double ms_between(RunClock::time_point a, RunClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// Adds the time of a scope to a total.
class Timed {
 public:
  explicit Timed(double& total) : total_(total) {}
  ~Timed() { total_ += ms_between(t0_, RunClock::now()); }
  Timed(const Timed&) = delete;
  Timed& operator=(const Timed&) = delete;

 private:
  double& total_;
  RunClock::time_point t0_ = RunClock::now();
};

}  // namespace l2
