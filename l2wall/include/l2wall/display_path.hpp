// A display path of the live run: how the pipeservers' frames become what the displays show.
// Two implementations sit beside each other, each written once for every backend: the DVI path
// (dvi_path.hpp: the emulated Lightning-2 over its board columns, in this process or over MPI)
// and the viz path (viz_path.hpp: compositors, the compositing server process or the column
// ranks). The live run drives one path as the lead, whose swaps are the run's frames, and with
// --path both a second one beside it, whose frames it takes and compares; it talks to this
// interface only.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_pictures.hpp"
#include "l2wall/run_report.hpp"
#include "l2wall/run_time.hpp"

namespace l2 {

class LiveBalance;

// What the live run checks while a path works; each throws RunFault to end the run.
struct RunWatch {
  std::function<void()> processes;  // every process of the run still running well
  std::function<void()> waiting;    // while waiting: the processes, the stall clock, the
                                    // back-channels served
};

// A swap of the lead path: frames up to `lowest` are on every display.
struct PathSwap {
  int lowest = 0;
  std::optional<std::uint64_t> refresh;  // the refresh it swapped in, on a refreshed path
  RunClock::time_point time{};
};

class DisplayPath {
 public:
  virtual ~DisplayPath() = default;

  // "vizserver": names the pictures of a path that is not the lead ("display-0-vizserver.png").
  virtual std::string label() const = 0;
  // "DVI path": how messages name it.
  virtual std::string name() const = 0;
  // What the pipeservers take part in on this path (a link and a back-channel, a server address).
  virtual void add_pipeserver_args(PipeserverLaunch& launch) const = 0;
  // Before the first frame: waits until the path can take in every pipeserver (up to `timeout`).
  virtual void open(PipeserverSet& pipeservers, std::chrono::milliseconds timeout,
                    const RunWatch& watch) = 0;

  // --- as the lead: its swaps pace the run ---------------------------------------------------
  // Whether it counts refreshes (and so measures the one-frame latency).
  virtual bool refreshed() const = 0;
  // One step towards frame `next` on the displays: the swap it made, if any. `records` get
  // each frame's input refresh and route time.
  virtual std::optional<PathSwap> step(int next, PipeserverSet& pipeservers,
                                       std::vector<FrameRecord>& records,
                                       const RunWatch& watch) = 0;
  // What the pipeservers that delivered wait for from this path ("READY", "SWAPPED").
  virtual std::string pipeservers_wait_for() const = 0;
  // Fault injection after a swap: line noise to the pipeservers; the bytes written.
  virtual std::uint64_t inject_noise(PipeserverSet& pipeservers) = 0;

  // --- what the displays show ------------------------------------------------------------
  // The displays of frame `frame`, waiting (watched) until this path shows it.
  virtual DisplayPictures frame_pictures(int frame, const RunWatch& watch) = 0;
  // Waits (watched) until this path shows frame `frame`, its pictures not needed. A path whose
  // pictures are far away (over MPI) need not bring them.
  virtual void take_frame(int frame, const RunWatch& watch) { (void)frame_pictures(frame, watch); }
  // What the displays show now, if anything reached them.
  virtual std::optional<DisplayPictures> shown() const = 0;
  // The frame the displays show; -1 before the first.
  virtual int frame_shown() const = 0;
  // Text files (name, text) saved beside the pictures of the frame just swapped in: what the
  // path knows of the displays at that refresh (the DVI path's frame-lock.txt).
  virtual std::vector<std::pair<std::string, std::string>> frame_files() const { return {}; }

  // --- faults ------------------------------------------------------------------------------
  // The defaults are those of a path with no process or stream of its own (the emulator in
  // this process): it never goes down and has nothing to say of a fault.
  // The path's own process ended or its stream broke.
  virtual bool down() { return false; }
  // Waits up to `grace` for a path that went down to be reaped, so a fault names how it ended.
  virtual void settle(std::chrono::milliseconds /*grace*/) {}
  // Each of these fails, with the line naming the path, when the path explains the fault; ok
  // when it does not. `shown`, `showing`: the frame the displays show, and those words.
  // The path's failure when it is the cause (it went down without saying why).
  virtual Status failure_as_cause(int /*shown*/, const std::string& /*showing*/) { return {}; }
  // The path's failure as the last explanation left.
  virtual Status failure(int /*shown*/, const std::string& /*showing*/) { return {}; }
  // A pipeserver that gave up on this path while it still runs: the path hangs, named so.
  virtual Status hang_behind(const LivePipeserver& /*h*/, int /*shown*/,
                             const std::string& /*showing*/) {
    return {};
  }
  // How messages name the path's own process ("compositing server (vizserver pid 4242)"), or
  // empty when it has none.
  virtual std::string process_name() const { return {}; }

  // --- ending ------------------------------------------------------------------------------
  // After the last frame: its process must end by itself, successfully.
  virtual void finish() {}
  // Ends its process, if any, and reaps it.
  virtual void shut_down() {}
  // What it says in the report, asked in path order (the lead first): its counts, how it paces
  // the run (RunTotals::pace, the lead's), and lines of its own for the summary (what it
  // proved, what crossed the network).
  virtual void add_totals(RunTotals& totals) const = 0;
  // A balanced run: the lead path serves the control channels while it waits for frames (the
  // pipeservers wait for each frame's layout), and checks its swaps against the layouts where it
  // can. The DVI paths (one machine and MPI) and the one-machine compositing server path lead one.
  virtual void follow_layouts(LiveBalance& /*balance*/, PipeserverSet& /*pipeservers*/) {}
  // --survive-host-loss: pipeserver `pipeserver` is lost and the run goes on without it. The DVI
  // path learns it from the PipeserverSet (its link carries no signal from then on); the
  // compositing server is told, so that its frames stop waiting for it.
  virtual void lose_pipeserver(int /*pipeserver*/) {}
};

}  // namespace l2
