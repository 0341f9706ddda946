// The options of `l2wall run` (RunOptions), and what they mean together: the combinations that
// make no run, the frames saved, the balancing asked for. The command line fills and checks
// them; run_wall() (live_run.hpp) runs them.
//
// Example:
//   RunOptions o;
//   o.path = PathChoice::Both;
//   o.compare = true;
//   if (const Status s = run_options_error(o); !s.ok()) fmt::print("{}\n", s.reason());
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "l2wall/path_choice.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct RunOptions {
  std::string wall;  // empty: the built-in default wall
  std::string scene = "mesh";
  std::vector<std::string> scene_args;  // --mesh, --camera-... as typed, for every pipeserver
  int frames = 10;
  std::string out = "l2wall-out";
  std::string keep = "last";           // every | last | none | K,L,...
  double refresh_hz = 60.0;            // 0: as fast as possible
  std::string pipeserver_program;      // the pipeserver executable
  std::string vizserver_program;       // the vizserver executable (the compositing server)
  std::string viz_host = "127.0.0.1";  // where the compositing server listens for tiles
  int viz_port = 0;                    // its port; 0: a free one, which it reports
  PathChoice path = PathChoice::Dvi;   // --path dvi | vizserver | both
  std::string balance;                 // static | strips | kd; empty: the wall's [balance]
  bool survive_host_loss = false;      // balancing: a dead pipeserver's tiles to the others
  std::optional<double> resistance;    // over the wall's [balance] resistance
  std::optional<double> tile_cost;     // over the wall's [balance] tile_cost
  bool compare = false;                // both: every display identical byte for byte on both paths
  int threads = 1;                     // emulator routing threads
  std::string link_codec = "auto";     // frames to the columns, tiles to the server (frame_delta)
  std::string renderer = "auto";       // every pipeserver's --renderer (renderer_choice.hpp)
  int start_timeout_ms = 60000;        // until every link carries its first frame
  int stall_timeout_ms = 5000;         // no display swap for this long: a pipeserver hangs
  // --mpi: a rank silent this long is lost (its host cut off); below the stall timeout, so that
  // a cut host is named as one, not as a pipeserver that hangs.
  int liveness_timeout_ms = 3000;
  int ready_timeout_ms = 1000;  // passed to the pipeservers (first frames can be slow)
  bool progress = true;
  std::string show;           // --show window | monitors: the displays on screen (live_show.hpp)
  std::string show_readback;  // --show-readback DIR: what the screen shows, written per frame
  std::string http;           // --http [ADDR:]PORT: the control page (control_page/); empty: none
  bool window_stdin = false;  // --window-stdin: a session's window commands, a line each, on stdin
  std::string tuio;           // --tuio [ADDR:]PORT: touch over TUIO (touch/); empty: no socket
  std::string vnc_password_file;  // --scene vnc: the server's password (`vncpasswd -f`'s file)
  // Fault injection, for tests and demonstrations.
  int noise_after = -1;      // after swapping this frame, write line noise to every pipeserver
  int inject_mismatch = -1;  // --compare: one pixel of display 0 of this frame changed on the
                             // vizserver side before comparing
  int drop_ready = -1;       // do not send READY for this frame to pipeserver 0 (it asks SYNC?)
};

// The frames whose displays are saved (--keep). Parses --keep; throws std::invalid_argument
// naming the bad item.
struct SavedFrames {
  bool every = false, last = false;
  std::set<int> frames;
  bool saves(int frame, int frame_count) const {
    return every || (last && frame == frame_count - 1) || frames.count(frame) > 0;
  }
};
SavedFrames parse_saved_frames(const std::string& text);

// Why these options cannot make a run ("--compare needs --path both", a bad --keep, a saved
// frame past the last one...), or nullopt. The command line checks it while parsing, so that
// such a mistake is a usage error; run_wall() throws std::invalid_argument with it.
Status run_options_error(const RunOptions& options);

// Extra pipeserver arguments of a run a person can pause (--show, --http): a paused run holds
// READY back as long as they like, so a pipeserver asks again with SYNC? every --ready-timeout
// ms for longer than it would otherwise. Empty for other runs.
std::vector<std::string> pausable_pipeserver_args(const RunOptions& options);

// The wall's [balance] with --balance over its mode, --resistance and --tile-cost over its
// own, and --survive-host-loss.
BalanceSpec run_balance(const RunOptions& options, const Wall& wall);
// Where a run's processes run, as balancing's refusals need it: on this machine, or as MPI
// ranks whose mpirun ends the job once one dies (its default) or keeps the job going
// (kMpirunKeepsJob's options).
enum class RunPlace { OneMachine, MpiEndingOnLoss, MpiKeepingJob };
inline constexpr const char* kMpirunKeepsJob =
    "--mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0";
// Why this run cannot balance as asked (--survive-host-loss without balancing, on both paths,
// or over MPI whose mpirun would end the job), or nullopt: one line naming the option or the
// wall file's line.
Status balance_refusal(const RunOptions& options, const Wall& wall, RunPlace place);
// Why this run cannot show its active stereo wall (an odd --frames would leave a frame's right
// eye unshown; sessions, desktops and movies are not done) or its packed one (pictures, movies,
// sessions and desktops are drawn one to one, not squeezed into each eye's half), or nullopt:
// one line naming the option. Any other wall: none. The same on one machine and over MPI.
Status stereo_refusal(const RunOptions& options, const Wall& wall);
// With survival asked for, what the run says as it starts: how many lost pipeservers the wall
// survives (tilelayout's survival line, the same words tilelayout prints), e.g.
// "--survive-host-loss: the wall survives the loss of any 3 of its 4 pipeservers (framebuffers
// 1024x768)"; empty without survival.
std::string survival_note(const RunOptions& options, const Wall& wall);

}  // namespace l2
