#include "run_core.hpp"

#include <unistd.h>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

RunCore::RunCore(const RunOptions& o)
    : options(o),
      saved(parse_saved_frames(o.keep)),
      wall(o.wall.empty() ? default_wall() : load_wall(o.wall)),
      layout(plan_layout(wall)) {
  frames.records.resize(static_cast<std::size_t>(o.frames));
  // A line redrawn with \r is for a terminal: in a log file, or through mpirun, it is one line
  // growing by a frame at every swap.
  options.progress = options.progress && isatty(STDERR_FILENO) == 1;
}

}  // namespace l2
