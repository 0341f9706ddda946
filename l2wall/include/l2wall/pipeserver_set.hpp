// The pipeservers of a live run: one `pipeserver --live` process per input, each with its DVI
// link (shared memory) and pty back-channel on the DVI path, and its report file. Starts them,
// watches them without blocking, takes their links in, serves their back-channels, and always
// ends and reaps them and removes the links a dead pipeserver left behind.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "balance/control_channel.hpp"
#include "base/child_process.hpp"
#include "dvi_link/dvi_link.hpp"
#include "l2wall/frame_stamp.hpp"
#include "l2wall/pipeserver_process.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "sync_backchannel/back_channel.hpp"
#include "sync_backchannel/pty_pair.hpp"
#include "tilelayout/planner.hpp"

namespace l2 {

// One pipeserver. Members are destroyed in reverse: the process is ended and reaped before the
// link reader and the pty go away. On one machine this run owns its link, pty and process;
// attached (an MPI rank) it has a back-channel and a process end named by its place only.
struct LivePipeserver {
  int pipeserver = 0;
  std::string link_name;
  std::string report_path;
  std::unique_ptr<PtyPair> pty;
  std::unique_ptr<ReadyChannel> channel;       // the serial line over the pty
  std::unique_ptr<DviReceiver> reader;         // shared memory on one machine
  std::unique_ptr<PipeserverProcess> process;  // never null once started or attached
  std::optional<ExitStatus> exit;
  std::uint64_t sequence = 0;  // frames published on its link so far
  int accepted = -1;           // the frame number of the last new frame the emulator took in
  // Where each frame's stamp is, by frame up to the last re-tiling (a balanced run re-tiles);
  // later frames use the last entry, frames before 0 the first.
  std::vector<StampSpot> stamps;
  const StampSpot& stamp(int frame) const {
    return stamps[static_cast<std::size_t>(
        std::clamp(frame, 0, static_cast<int>(stamps.size()) - 1))];
  }
  // Balancing: this end of the pipeserver's control channel (TIMES in, LAYOUT out): a socket on one
  // machine, MPI messages with an MPI rank.
  std::unique_ptr<ControlChannel> control;
  // A session run's: this end of the pipeserver's windows channel (WANT in, WINDOWS out).
  std::unique_ptr<ControlChannel> windows;
  // Fault injection: a READY held back until the pipeserver asks with SYNC?.
  std::optional<int> held_ready;
  // It died and the run went on without it (--survive-host-loss): its link is no input any
  // more, and nothing waits for it or blames it.
  bool lost = false;
};

// What every pipeserver is started with.
struct PipeserverLaunch {
  std::string program;  // the pipeserver executable
  std::string wall;     // wall file; empty: the built-in default wall
  std::string scene;
  std::vector<std::string> scene_args;  // scene and camera options (--mesh FILE, ...)
  std::filesystem::path out;            // pipeserver-<i>.log go here
  int frames = 0;
  int ready_timeout_ms = 0;
  bool dvi = true;          // DVI link and back-channel
  std::string viz_address;  // HOST:PORT of the compositing server; empty: none
  std::string link_codec;   // --link-codec of every pipeserver; empty: the pipeserver's own
  std::string renderer;     // --renderer of every pipeserver; empty: the pipeserver's own (auto)
  std::vector<std::string> extra_args;  // appended to every pipeserver's arguments
  std::vector<std::string> env;         // "NAME=value" added to every pipeserver's environment
  bool control = false;  // a control channel per pipeserver (--control-fd): balancing
  bool windows = false;  // a windows channel per pipeserver (--windows-fd): a session's windows
};

// The command line of pipeserver `h`'s pipeserver process.
std::vector<std::string> pipeserver_argv(const PipeserverLaunch& launch, const LivePipeserver& h);

class PipeserverSet {
 public:
  // Starts one process per pipeserver of the layout.
  void start(const PipeserverLaunch& launch, const TileLayout& layout);
  // What a pipeserver this process did not start is reached through.
  struct RemoteEnd {
    std::unique_ptr<PipeserverProcess> process;  // remote_pipeserver_process(its place)
    std::unique_ptr<ReadyChannel> channel;       // its back-channel
    std::unique_ptr<ControlChannel> control;     // balancing (PipeserverLaunch::control), else null
    std::unique_ptr<ControlChannel> windows;     // a vnc run's desktop, else null
  };
  // Pipeservers this process did not start (MPI ranks, mpi/): no link reader here; `connect` gives
  // each one's ends. Their links are taken in elsewhere, and the path that does records
  // LivePipeserver::sequence.
  void attach(const PipeserverLaunch& launch, const TileLayout& layout,
              const std::function<RemoteEnd(int pipeserver)>& connect);

  // Frames `from` on carry their stamps where `layout` puts them.
  void place_stamps(const TileLayout& layout, int from);

  std::deque<LivePipeserver>& all() { return pipeservers_; }
  const std::deque<LivePipeserver>& all() const { return pipeservers_; }
  // The pipeservers still taking part, all but those lost: a view of all() for a range-for,
  // nothing copied. (Not std::views::filter: clang 14, the sanitizer builds' compiler, cannot
  // compile libstdc++ 12's views.)
  template <class It>
  class Serving {
   public:
    struct Iterator {
      It at, end;
      auto& operator*() const { return *at; }
      Iterator& operator++() {
        at = skip_lost(++at, end);
        return *this;
      }
      bool operator==(const Iterator& other) const { return at == other.at; }
    };
    Serving(It begin, It end) : begin_(skip_lost(begin, end)), end_(end) {}
    Iterator begin() const { return {begin_, end_}; }
    Iterator end() const { return {end_, end_}; }

   private:
    static It skip_lost(It at, It end) {
      while (at != end && at->lost) ++at;
      return at;
    }
    It begin_, end_;
  };
  auto serving() { return Serving(pipeservers_.begin(), pipeservers_.end()); }
  auto serving() const { return Serving(pipeservers_.begin(), pipeservers_.end()); }

  // The run goes on without `h`, which ended (--survive-host-loss): from now on its link is
  // taken in as an input without a signal (its last frame stays in the shared memory, and would
  // hold up every swap-lock group it fed), and it is never polled, waited for or blamed.
  void lose(LivePipeserver& h) { h.lost = true; }

  // Polls every pipeserver; returns the first whose end is a fault: it ended badly, or before it
  // delivered every frame. (A pipeserver ends well only after its last frame was swapped, which it
  // may learn from the compositing server before this process has that frame: not a fault.)
  // The caller words it with describe_end.
  LivePipeserver* poll_ended();
  // Polls every pipeserver; the first that was killed by a signal (never the effect of another
  // process's fault, so the cause when several processes ended at once).
  LivePipeserver* killed_by_signal();
  // "pipeserver 1 (pid 4242) killed by signal 9 (Killed) while rendering frame 57; " + on_displays
  // (what the displays keep, e.g. "the displays keep frame 56").
  std::string describe_end(const LivePipeserver& h, const std::string& on_displays) const;
  // The same without what the displays keep.
  std::string ended_how(const LivePipeserver& h) const;

  // Opens every pipeserver's DVI link and waits until each carries a first frame; `check` runs in
  // between (it throws for a pipeserver that died). Throws RunFault naming the pipeservers still
  // silent.
  void open_links(std::chrono::milliseconds timeout, const std::function<void()>& check);
  // Takes in every link; true when some link has a frame not seen before.
  bool take_in(std::vector<InputFrame>& inputs);
  // Answers SYNC? on every back-channel and sends a held-back READY once its pipeserver asked.
  void serve_channels();

  // Fault injection: writes line noise to every back-channel; returns the bytes written.
  std::uint64_t inject_noise();

  // Pipeservers that have not delivered frame `shown` (the one the displays wait for), as
  // "pipeserver 2 (pid 4242), ...": on the DVI path their links say so, otherwise their
  // reports (one line per frame).
  std::string late_pipeservers(int shown) const;
  // How many frames the pipeserver delivered: published on its link, or reported.
  int delivered(const LivePipeserver& h) const;
  // The pipeserver that stopped answering while the displays wait for frame `shown`: still running
  // (or stopped by a signal) and frame `shown` not delivered; a stopped one first. Nullptr if
  // none: every late pipeserver has ended, or none is late.
  const LivePipeserver* hung_pipeserver(int shown);
  // " (stopped by a signal)" for a pipeserver that is, otherwise empty.
  static std::string stopped_note(const LivePipeserver& h);

  // After the last frame: waits for every pipeserver to end by itself, serving the back-channels.
  // Throws RunFault for a pipeserver that ends badly or not within `timeout`.
  void finish(std::chrono::milliseconds timeout);
  // Asks every pipeserver still running to end (SIGTERM), without waiting.
  void request_stop();
  // Ends every pipeserver still running (SIGTERM, then SIGKILL), reaps it, removes its link.
  void shut_down();

 private:
  std::deque<LivePipeserver>
      pipeservers_;  // a deque: pipeservers never move, the back-channels refer to their ptys
  bool dvi_ = true;
  int frames_ = 0;  // every pipeserver renders this many
};

}  // namespace l2
