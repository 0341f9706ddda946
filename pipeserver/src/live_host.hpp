// `pipeserver --live`: one host of a live run (l2wall run). It renders frames 0..N-1, writes
// each into its DVI link (POSIX shared memory) and, from the second frame on, waits for the
// READY of the previous frame on its serial back-channel before publishing (spec §6.1).
#pragma once

#include <string>

#include "pipeserver/live_exit.hpp"
#include "pipeserver/scene.hpp"

namespace l2 {

struct LiveHostOptions {
  std::string wall;  // empty: the built-in default wall
  int server = 0;
  std::string scene = "mesh";
  SceneOptions scene_options;
  int frames = 10;
  std::string link;         // shared-memory name this host creates ("/l2-..."); empty: none
  std::string backchannel;  // serial device (a pty slave) the READYs arrive on (with link)
  std::string viz;          // "host:port" of a compositing server to send tiles to; empty: none
  std::string report;       // file: one line per frame (render and wait times)
  int ready_timeout_ms = 200;
  int ready_retries = 3;
};

// Every frame carries its frame number in the first pixel of the host's first tile (24 bits,
// R low byte), so the run can tell from the displays which frame they show.
inline constexpr int kStampBits = 24;

// Returns the process exit code: 0 on success, kExitNoReady when READY never came (message on
// stderr). Throws viz::VizError when the compositing server is lost (kExitLostCompositingServer).
int run_live_host(const LiveHostOptions& options);

}  // namespace l2
