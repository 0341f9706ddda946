// The compositors of the viz path as it drives them (viz_path.hpp): what composes the
// pipeservers' tiles into displays and says when a frame is composed everywhere. Two
// implementations sit beside each other: the compositing server process of one machine
// (server_compositor.hpp) and the board column ranks of an MPI run, each compositing its own
// displays (mpi/src/mpi_compositors.hpp). What is the same on both (waiting for a frame while
// the run is watched, balancing, pictures for the run) is the path's, written once.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "base/result.hpp"
#include "l2wall/display_path.hpp"

namespace l2 {

class Compositors {
 public:
  virtual ~Compositors() = default;

  // What the pipeservers take part in (the server's address and token); nothing for ranks
  // started with theirs.
  virtual void add_pipeserver_args(PipeserverLaunch& /*launch*/) const {}
  // Takes in what was composed (over MPI: SWAPPED to the pipeservers once a frame is composed
  // on every column); true once frame `frame` is, waiting up to `wait` for it.
  virtual bool composed(int frame, std::chrono::milliseconds wait) = 0;
  // The displays of frame `frame`, composed; brought here where they are far.
  virtual DisplayPictures pictures(int frame) = 0;
  // The last displays brought here, if any, and their frame (-1: none).
  virtual std::optional<DisplayPictures> shown() const = 0;
  virtual int frame_shown() const = 0;
  // How long a frame may take before the compositors are named late (late()); nullopt when the
  // run's own stall check names them.
  virtual std::optional<std::chrono::milliseconds> frame_limit() const { return std::nullopt; }
  virtual std::string late(int /*frame*/) const { return {}; }

  // --- faults, as DisplayPath's (display_path.hpp) ---------------------------------------------
  virtual bool down() { return false; }
  virtual void settle(std::chrono::milliseconds /*grace*/) {}
  virtual Status failure_as_cause(int /*shown*/, const std::string& /*showing*/) { return {}; }
  virtual Status failure(int /*shown*/, const std::string& /*showing*/) { return {}; }
  virtual Status hang_behind(const LivePipeserver& /*h*/, int /*shown*/,
                             const std::string& /*showing*/) {
    return {};
  }
  virtual std::string process_name() const { return {}; }

  // --survive-host-loss: frames stop waiting for `pipeserver`.
  virtual void lose(int /*pipeserver*/) {}
  virtual void finish() {}
  virtual void shut_down() {}
};

}  // namespace l2
