// `l2wall view OUT`: the control page of a finished run, served from its --out folder: the
// wall with the displays of a saved frame (the last one kept, or --frame K), the summary, the
// pipeservers' times from their logs, the tiles of that frame's layout, and every picture the
// folder holds (kept frames, the displays after a fault, screenshots, the golden check's and the
// verifier's pictures) as links. Nothing to steer: the run is over. Serves until Ctrl-C.
#pragma once

namespace CLI {
class App;
}

namespace l2 {

// Adds `view` to `app`; it runs during parsing and ends it with its exit code (as `golden`).
void add_view_command(CLI::App& app);

}  // namespace l2
