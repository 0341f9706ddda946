// Exit codes of `pipeserver --live` beyond 0 (done), 1 (failed) and 2 (usage). `l2wall run`
// reads them to tell a cause from an effect when a run fails.
#pragma once

namespace l2 {

// READY never came on the serial back-channel (after the retries with SYNC?).
inline constexpr int kExitNoReady = 3;
// The compositing server could not be reached, closed the connection, reported an error or
// stopped answering (no SWAPPED in time): the pipeserver lost it, it did not fail by itself.
inline constexpr int kExitLostCompositingServer = 4;

// A pipeserver that ended so gave up waiting on another part of the run: its end is the effect
// of another's fault, which the run names instead (on one machine and over MPI alike).
inline constexpr bool gave_up_waiting(int exit_code) {
  return exit_code == kExitNoReady || exit_code == kExitLostCompositingServer;
}

}  // namespace l2
