// Where the parts of a live run run: one machine (pipeserver child processes on shared-memory
// DVI links and pty back-channels, this process the Lightning-2), or other backends beside it
// (mpi_link/: MPI ranks). The live run makes its display paths and starts its pipeservers through
// this, once; nothing else in it knows which backends run.
#pragma once

#include <memory>
#include <string>

#include "l2wall/display_path.hpp"
#include "l2wall/live_run.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

struct VizLaunch;  // vizserver_process.hpp

class RunBackends {
 public:
  virtual ~RunBackends() = default;
  virtual std::unique_ptr<DisplayPath> dvi_path(const TileLayout& layout,
                                                const RunOptions& options) const = 0;
  virtual std::unique_ptr<DisplayPath> viz_path(const TileLayout& layout,
                                                const VizLaunch& launch) const = 0;
  virtual void start_pipeservers(PipeserverSet& pipeservers, const PipeserverLaunch& launch,
                                 const TileLayout& layout) const = 0;
  // Whether the run can end its pipeservers before their last frame, as a stop from the control
  // page asks: child processes are signalled; MPI ranks on other hosts cannot be, they wait for
  // READY (mpirun ends them all on Ctrl-C).
  virtual bool stops_pipeservers_early() const { return true; }
  // Whether `line` (a fault's, without "l2wall: ") is on stderr already: MPI's watch of the
  // ranks prints a loss's line itself when the run is slow to take it up (mpirun may be ending
  // the coordinator).
  virtual bool fault_said(const std::string& line) const {
    (void)line;
    return false;
  }
};

// Child processes, shared memory, ptys, the compositing server process.
const RunBackends& one_machine_backends();

// What every pipeserver of a run of `options` is started with (before a path adds its part).
PipeserverLaunch pipeserver_launch(const RunOptions& options);

// The picture and session scenes' --picture-cache-mb, where not given, added to what every
// pipeserver is started with: default_picture_cache_mb (pipeserver/picture_cache.hpp) of a
// machine of `physical_mb` running `pipeservers`. Other scenes are left as they are.
void add_picture_cache_default(PipeserverLaunch& launch, int pipeservers, double physical_mb);

// run_wall() on the given backends.
int run_wall(const RunOptions& options, const RunBackends& backends);

}  // namespace l2
