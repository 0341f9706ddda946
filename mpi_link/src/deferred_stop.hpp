// Ctrl-C on mpirun ends an MPI run by SIGTERM to every rank at once (SIGKILL a second later):
// the coordinator stops its frames and writes the run's report, and the other ranks must live
// until it has (their end would leave it waiting on them). So every rank but the coordinator
// only records the signal (base/stop_signals.hpp); it ends on the coordinator's word
// (liveness.hpp), or, signalled alone and never told, as the signal would have ended it once
// kStopGrace is out.
#pragma once

#include <chrono>

#include "base/stop_signals.hpp"

namespace l2 {

// Far above what the coordinator takes to stop its frames and write the report.
inline constexpr std::chrono::seconds kStopGrace{5};

}  // namespace l2
