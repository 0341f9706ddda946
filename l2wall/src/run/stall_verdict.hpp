// When a run whose displays stopped swapping ends in a stall fault (--stall-timeout). The timeout
// is there for a process that stopped or hung, and the fault names it: a pipeserver that has not
// delivered the frame the displays wait for, or the compositing server that has not shown it.
// When every one of them has delivered, there is nobody to name: the wait is the machine's (a
// loaded machine starves the coordinator and the board column ranks for a second or more), and
// a column rank that hangs is named by the path's own watch. The run then waits on, but not
// forever: a hang that nobody can be named for still ends the run, kUnnamedStallFactor times the
// timeout after the last swap.
#pragma once

namespace l2 {

inline constexpr int kUnnamedStallFactor = 10;

inline bool stall_ends_run(double waited_ms, int limit_ms, bool someone_to_name) {
  const double limit =
      someone_to_name ? limit_ms : static_cast<double>(limit_ms) * kUnnamedStallFactor;
  return waited_ms >= limit;
}

}  // namespace l2
