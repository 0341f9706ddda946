// `l2wall run --http [ADDR:]PORT`: the control page of a live run (control_page/). The run
// tells it, after a swap, where it is; a few times a second that becomes the page's state (with
// the displays' pictures, the current tiles and the pipeservers' latest times, read from their
// logs as they grow). The page's requests come back to the run through requests(), which the
// run takes at frame boundaries: pause, resume, save, stop, a balance mode.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "balance/control_messages.hpp"
#include "control_page/control_server.hpp"
#include "l2wall/run_options.hpp"
#include "l2wall/run_pictures.hpp"
#include "l2wall/run_time.hpp"
#include "pipeserver_log.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// Where the run is, as the run knows it, at a swap (or while paused).
struct PageMoment {
  int frame = -1;  // the last frame on every display
  double fps = 0;
  long latency_frames = -1;
  bool paused = false;
  std::vector<PageTile> tiles;       // of `frame`'s layout
  std::vector<bool> lost;            // by pipeserver: survived its loss
  std::vector<double> recent_route;  // the emulator's route ms of the last frames; none: no
  double refresh_hz = 0;             // emulator (the vizserver path)
  std::string balance_mode;          // "" for a run that does not balance
  std::vector<PageWindow> windows;   // a session's, at `frame`
  bool windows_movable = false;
  int share_slots = 0;  // screens a browser may share at once
};

class LivePage {
 public:
  // Listens (throws std::runtime_error in one line when it cannot) and prints the page's URL
  // with the run's token on stderr.
  // `stoppable`: whether a stop from the page can end the run (RunBackends).
  LivePage(const RunOptions& o, const Wall& wall, bool stoppable);

  // The pipeservers' logs (pipeserver-<i>.log) and where each runs, once they are started.
  void watch_pipeservers(const std::vector<std::string>& logs,
                         const std::vector<std::string>& places);

  // Whether the page should be told again: a few times a second, or at once after a change the
  // user made (a pause, a save).
  bool due() const;
  // Whether a page has read the state lately: the displays' pictures are gathered for the page
  // only then.
  bool watched() const;
  // The state and, when given, the displays' pictures of moment.frame.
  void publish(const PageMoment& moment, const DisplayPictures* pictures);
  // Something the page lists as it happens (a save, a stale frame, a lost pipeserver, a fault).
  void event(int frame, std::string text);

  std::vector<ControlRequest> requests();
  // The screens browsers share into the run: their frames, as the server takes them in.
  std::shared_ptr<ShareInbox> shares() const { return server_->shares(); }
  // The run's decision on a request taken: the page lists it as an event, and the HTTP request
  // that asked for it is answered with it.
  void decide(int frame, const ControlRequest& request, ControlDecision decision);

  // The run is over (`how`: the summary's first line, or the fault): the page says so and gets a
  // moment to read it before the server ends with the run.
  void end(const std::string& how, const std::string& summary);

 private:
  void read_logs();
  std::string limited_by(const PageMoment& moment) const;

  std::unique_ptr<ControlServer> server_;
  RunState state_;
  std::vector<PipeserverLogTail> logs_;
  RunClock::time_point last_publish_{};
  bool publish_now_ = true;
};

// A page's state with the wall filled in (name, canvas, displays), for a live run or a finished
// one.
RunState wall_state(const Wall& wall);
// What a pipeserver's log line tells the page of it: a frame's times, or its back-channel totals.
void take_log_line(PagePipeserver& pipeserver, const PipeserverLogLine& line);

// The tiles of a layout as the page draws them: canvas rectangles and their pipeservers.
std::vector<PageTile> page_tiles(const TileLayout& layout);
std::vector<PageTile> page_tiles(const LayoutMessage& layout);

}  // namespace l2
