// The stop signals (SIGINT: Ctrl-C; SIGTERM: kill, or mpirun ending a job), recorded rather than
// taken at once: a live run stops its frames and writes its report first (l2wall's
// stop_signal.hpp), and an MPI rank waits for its coordinator's word (mpi_link's
// deferred_stop.hpp). One recorder for every process of the project.
//
// Owns: the handlers, the signal recorded, and the end by it.
#pragma once

namespace l2 {

// Installs the recording handlers for SIGINT and SIGTERM.
void catch_stop_signals();
// The stop signal recorded (SIGINT, SIGTERM), or 0.
int stop_signal_received();
// Ends this process as the recorded signal's default action does, so its status says the
// signal (a shell's 130 for Ctrl-C, 143 for SIGTERM). Only once one was recorded.
[[noreturn]] void end_by_stop_signal();

}  // namespace l2
