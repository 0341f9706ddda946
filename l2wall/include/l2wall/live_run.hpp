// `l2wall run`: the live run on one machine. One pipeserver process per input renders into its
// DVI link (shared memory) and waits for READY on its own pty back-channel; this process is the
// Lightning-2: it takes in every link at the refresh rate, routes, swaps, sends READY, writes
// the displays it was asked to save and a per-frame report, and proves the one-frame latency
// from frame numbers stamped into the pixels. With --path vizserver or both, the compositing
// server runs as its own process (`vizserver`): the pipeservers send it their tiles over TCP
// and it streams the composed displays back to this process (docs/vizserver-protocol.md).
#pragma once

#include "l2wall/run_options.hpp"

namespace l2 {

// Returns the exit code: 0 when every frame reached the displays with one frame of latency.
int run_wall(const RunOptions& options);

}  // namespace l2
