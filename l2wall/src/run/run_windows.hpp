#pragma once

#include <unistd.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "control_page/control_inbox.hpp"
#include "control_page/run_state.hpp"
#include "control_page/share_inbox.hpp"
#include "desktops/live_desktop.hpp"
#include "desktops/live_windows.hpp"
#include "desktops/session_desktops.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_options.hpp"
#include "line_reader.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// The windows and desktops of a live run: a session run's windows (which the control page and
// --window-stdin move), its vnc windows' desktops, and a vnc run's desktop. It owns their
// connections, made before any pipeserver starts, and answers the pipeservers' requests for
// them; it may not advance frames, end processes or write into OUT (the report writer takes its
// summary and windows.txt).
class RunWindows {
 public:
  // Connects what the scene of `o` shows (a session's windows, a vnc desktop); a desktop that
  // cannot be reached throws std::runtime_error in one line. `balanced`: the run balances,
  // which a desktop sent for the wall file's tiles refuses.
  void start(const RunOptions& o, const TileLayout& layout, bool balanced);
  // Whether the pipeservers take WINDOWS lines (a session run, and a vnc run's desktop).
  bool any() const { return windows_ != nullptr || desktop_ != nullptr; }
  // Answers what the pipeservers asked for (WANT comes before each READY wait).
  void serve(PipeserverSet& pipeservers);
  // A window command, taken from the next frame whose windows are decided: every pipeserver
  // moves it then. Returns what was done or why not, as the page or stderr says it, with the
  // status the control page answers: 400 for words it cannot read, 404 for no such window, 409
  // for a run whose windows do not move.
  ControlDecision command(const std::string& command, const PipeserverSet& pipeservers);
  // A screen a browser shares ("W H CX CY NAME", ControlRequest's Share): a free share slot's
  // window, from the next frame decided, fed from `inbox`. 409 when the session takes no
  // shares or all its share windows are in use; 400 for words it cannot read.
  ControlDecision share(const std::string& request, const std::shared_ptr<ShareInbox>& inbox,
                        const PipeserverSet& pipeservers);
  // How many screens may be shared at once; 0: none.
  int share_slots() const;
  // --window-stdin: the whole lines waiting on stdin, without waiting for more.
  std::vector<std::string> stdin_commands() { return stdin_lines_.take(); }
  // Whether the pipeservers take WINDOWS lines (over MPI too, --mpi-windows): all of a session's.
  static bool moving_here(const PipeserverSet& pipeservers);
  // A session's windows at `frame`, as the control page draws them.
  std::vector<PageWindow> page_windows(int frame) const;
  // A session's windows at `frame` as every pipeserver draws them (back to front); none without
  // a session.
  std::vector<WindowPlace> shown_at(int frame) const;
  bool session() const { return windows_ != nullptr; }

  // The summary's lines of the windows and desktops.
  std::string summary() const;
  // The files of OUT they add to the report (windows.txt).
  std::vector<std::pair<std::string, std::string>> files() const;

 private:
  void start_windows(const RunOptions& o, const TileLayout& layout, bool balanced);
  void start_session_desktops(const Session& session, const TileLayout& layout, bool balanced);
  void start_desktop(const RunOptions& o, const TileLayout& layout, bool balanced);
  // A share's window closed (`command` closed `id`): its slot is free, its frames refused.
  void closed(int id);

  std::unique_ptr<LiveWindows> windows_;               // a session run's windows
  std::unique_ptr<LiveDesktop> desktop_;               // a vnc run's desktop
  std::unique_ptr<SessionDesktops> session_desktops_;  // a session's vnc windows' desktops
  LineReader stdin_lines_{STDIN_FILENO};               // --window-stdin
  std::shared_ptr<ShareInbox> share_inbox_;            // the page's, once a screen is shared
  int canvas_width_ = 0, canvas_height_ = 0;           // where shares are placed
};

}  // namespace l2
