#pragma once

#include <string>

#include "progress_line.hpp"
#include "run_core.hpp"

namespace l2 {

// The watchdog of a live run: whether every process of the run still runs well, and when one
// does not, which is the cause. It names the cause in a RunFault: a stop signal, a process that
// ended (a process killed by a signal before a compositing server that died without saying
// why, before a pipeserver that exited badly), a path that went down, or no display swap for
// --stall-timeout. Under --survive-host-loss it lets the run go on without a lost pipeserver,
// telling the balance coordinator, the pipeservers and the paths. It may not advance frames,
// end processes or write into OUT; its only output besides the fault is the line (and page
// event) of a pipeserver survived.
class Watchdog {
 public:
  Watchdog(RunCore& core, const ProgressLine& progress) : core_(core), progress_(progress) {}

  // A stop signal, a process that ended early, or a path whose process or stream broke: throws
  // a RunFault naming the cause.
  void check_processes();
  // No display swap for --stall-timeout (--start-timeout before the first): throws a RunFault
  // naming what hangs.
  void check_stall();
  // What the displays show now, for a fault message. With both paths they can differ by a
  // frame: the emulator swapped frame K while the run waited for the compositing server's K.
  std::string displays_showing() const;

 private:
  bool survive(LivePipeserver& h);
  std::string blame();
  std::string blame_given_up(const LivePipeserver& ended);
  std::string stall_note() const;
  std::string waiting_for(const LivePipeserver& h) const;
  std::string server_process() const;

  RunCore& core_;
  const ProgressLine& progress_;
};

}  // namespace l2
