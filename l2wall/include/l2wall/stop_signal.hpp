// Ctrl-C or SIGTERM during a live run: the run stops as q does under --show — the frames
// shown so far are the run, its processes are ended and their shared memory removed, the
// report and summary are written — and l2wall exits 128 + the signal (130 for Ctrl-C), as a
// shell reports a command a signal ended. Before any frame was shown there is nothing to
// report: the run ends through its fault path, with the same exit status.
#pragma once

#include <string>

#include "base/stop_signals.hpp"  // catch_stop_signals, stop_signal_received

namespace l2 {

// The exit status of a run a stop signal ended: 128 + the signal.
inline int stopped_exit_status(int signal) {
  return 128 + signal;
}
// Throws RunFault "stopped by signal 15 (Terminated) at frame K; " + on_displays once one of
// them arrived; `shown` is the number of frames on the displays (K), `on_displays` says what
// they show.
void check_stop_signal(int shown, const std::string& on_displays);

}  // namespace l2
