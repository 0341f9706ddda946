#pragma once

#include <string>

#include "run_core.hpp"
#include "run_windows.hpp"
#include "run_writer.hpp"
#include "watchdog.hpp"

namespace l2 {

// Page steering: what the control page (--http) asks of a live run, taken at frame boundaries,
// and what the run tells it. It owns the steering state (a pause, a stop, the counts for the
// summary) and publishes where the run is after each swap. A pause holds the run here while the
// watchdog still watches the pipeservers. It may not advance frames or end processes: a stop is
// a request the frame loop ends on; saves go through the report writer, window moves through
// the run's windows, balance modes through the balance coordinator. Without a page it does
// nothing.
class PageSteering {
 public:
  // `stoppable`: whether a stop from the page can end the run (RunBackends).
  PageSteering(RunCore& core, const RunWatch& watch, Watchdog& watchdog, RunWindows& windows,
               RunWriter& writer, bool stoppable)
      : core_(core),
        watch_(watch),
        watchdog_(watchdog),
        windows_(windows),
        writer_(writer),
        stoppable_(stoppable) {}

  // Once the pipeservers are started: their logs and places, for the page to show.
  void watch_pipeservers();
  // The page's requests at a frame boundary; a pause holds the run here (nothing taken in, no
  // READY sent, the pipeservers wait). False once the page asked to stop and a frame is shown.
  bool follow();
  // After a swap: the page told where the run is, when it is due.
  void after_swap();
  // "control page: 1 pause, 2 saves, stopped from the page at frame 57\n"; empty without a page.
  std::string summary() const;
  // The run ended (`how`: the summary's first line, or the fault).
  void end(const std::string& how, const std::string& summary);

 private:
  void hold_while_paused();
  void take_requests();
  ControlDecision take_request(const ControlRequest& r, int frame);
  ControlDecision stop(int frame);
  ControlDecision save(int frame);
  ControlDecision switch_balance(const std::string& mode, int frame);
  void publish();
  PageMoment moment() const;

  RunCore& core_;
  const RunWatch& watch_;
  Watchdog& watchdog_;
  RunWindows& windows_;
  RunWriter& writer_;
  const bool stoppable_;
  bool paused_ = false, stop_ = false;
  int pauses_ = 0, saves_ = 0;
  int stopped_at_ = -1;  // the last frame on the displays when the page stopped the run
};

}  // namespace l2
