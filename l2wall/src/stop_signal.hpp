// Ctrl-C or SIGTERM during a live run: the run stops through its normal fault path, so its
// processes are ended and their shared memory removed instead of left behind.
#pragma once

#include <string>

namespace l2 {

// Installs the handlers for SIGINT and SIGTERM (they only record the signal).
void catch_stop_signals();
// Throws RunFault "stopped by signal 15 (Terminated) at frame K; " + on_displays once one of
// them arrived; `shown` is the number of frames on the displays (K), `on_displays` says what
// they show.
void check_stop_signal(int shown, const std::string& on_displays);

}  // namespace l2
