// Ctrl-C on mpirun ends an MPI run by SIGTERM to every rank at once (SIGKILL a second later):
// the coordinator stops its frames and writes the run's report, and the other ranks must live
// until it has (their end would leave it waiting on them). So every rank but the coordinator
// only records the signal; it ends on the coordinator's word (liveness.hpp), or, signalled
// alone and never told, as the signal would have ended it once kStopGrace is out.
//
// Owns: the handlers, the signal recorded, and the end by it.
#pragma once

#include <chrono>

namespace l2 {

// Far above what the coordinator takes to stop its frames and write the report.
inline constexpr std::chrono::seconds kStopGrace{5};

// Installs the recording handlers for SIGINT and SIGTERM.
void defer_stop_signals();
// The stop signal recorded (SIGINT, SIGTERM), or 0.
int deferred_stop_signal();
// Ends this process as the recorded signal's default action does (its status says the signal).
[[noreturn]] void end_by_deferred_signal();

}  // namespace l2
