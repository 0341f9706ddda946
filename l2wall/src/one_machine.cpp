// The one-machine backends of a live run: pipeserver child processes on shared-memory DVI links
// and pty back-channels, this process the Lightning-2 (DviPath over LocalColumns), the
// compositing server as a child process (VizPath). The MPI backends are beside it in
// mpi/src/mpi_run.cpp.
#include <memory>

#include "l2wall/dvi_path.hpp"
#include "l2wall/run_backends.hpp"
#include "l2wall/viz_path.hpp"
#include "local_columns.hpp"
#include "server_compositor.hpp"

namespace l2 {
namespace {

class OneMachine final : public RunBackends {
 public:
  std::unique_ptr<DisplayPath> dvi_path(const TileLayout& layout,
                                        const RunOptions& o) const override {
    return std::make_unique<DviPath>(
        layout, o,
        std::make_unique<LocalColumns>(layout.wall, o.threads, layout.pipeservers.size()));
  }
  std::unique_ptr<DisplayPath> viz_path(const TileLayout& layout,
                                        const VizLaunch& launch) const override {
    return std::make_unique<VizPath>(std::make_unique<ServerCompositor>(launch),
                                     ColourStage(layout.wall));
  }
  void start_pipeservers(PipeserverSet& pipeservers, const PipeserverLaunch& launch,
                         const TileLayout& layout) const override {
    pipeservers.start(launch, layout);
  }
};

}  // namespace

const RunBackends& one_machine_backends() {
  static const OneMachine backends;
  return backends;
}

}  // namespace l2
