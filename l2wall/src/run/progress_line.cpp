#include "progress_line.hpp"

#include <cstdio>

namespace l2 {

void ProgressLine::frames(RunClock::time_point now) {
  if (!core_.options.progress) return;
  shown_ = true;
  const FrameLedger& f = core_.frames;
  const double s = ms_between(f.totals.start, now) / 1000.0;
  // Ended by erase-to-end-of-line (only ever drawn on a terminal): it overwrites the longer
  // line of the wait for the first frames.
  std::fprintf(stderr, "\rl2wall: frame %d/%d on the displays, %.1f fps\033[K", f.shown,
               core_.options.frames, s > 0 ? f.shown / s : 0.0);
  std::fflush(stderr);
}

void ProgressLine::waiting() {
  if (!core_.options.progress) return;
  const auto now = RunClock::now();
  if (!waiting_since_) waiting_since_ = now;
  const auto seconds = static_cast<int>(ms_between(*waiting_since_, now) / 1000.0);
  if (seconds < 1 || seconds == waiting_shown_) return;
  waiting_shown_ = seconds;
  shown_ = true;
  std::fprintf(stderr,
               "\rl2wall: waiting for the pipeservers' first frames, %d s (each reads its "
               "model or picture first; --start-timeout %d ms)",
               seconds, core_.options.start_timeout_ms);
  std::fflush(stderr);
}

}  // namespace l2
