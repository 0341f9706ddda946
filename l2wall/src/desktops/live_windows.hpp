// A session run's windows on the coordinator (docs/session-file.md): where each window is now,
// changed by commands from the control page, and the WINDOWS line of every frame. A frame's
// line is decided the first time a pipeserver asks for it (WANT) and sent alike to every
// pipeserver that asks, so all of them move a window in the same frame, as they switch layouts
// (live_balance.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "balance/control_messages.hpp"
#include "tilelayout/session_file.hpp"

namespace l2 {

class PipeserverSet;
class SessionDesktops;

class LiveWindows {
 public:
  explicit LiveWindows(const Session& session);

  // Why a command was not taken; `why` empty when it was.
  struct Refusal {
    std::string why;              // one line
    bool no_such_window = false;  // its ID names no window shown (closed, or never there)
  };
  // "move ID X Y W H" (its top-left and size on the canvas), "raise ID" (in front of the
  // others), "close ID": taken from the next frame decided.
  Refusal command(std::string_view line);
  // Shows window `id` (a share's, session_shares.hpp) at `r`, in front of the others, from the
  // next frame decided, which it returns. Its source is "share".
  int open(int id, const Rect& r);
  // The first frame whose windows are not decided yet: what a command changes from.
  int next_frame() const { return static_cast<int>(lines_.size()); }
  // Frame `frame`'s WINDOWS line, deciding every frame up to it (each with the commands taken
  // since the one before).
  const std::string& line_for(int frame);
  // Answers every WANT waiting, each with its frame's WINDOWS line and then `desktops`' lines
  // for that pipeserver and frame (a session with vnc windows). Throws RunFault for a line
  // that is not one, or a desktop's server gone.
  void serve(PipeserverSet& pipeservers, SessionDesktops* desktops = nullptr);

  // The windows of `frame` (back to front) as every pipeserver draws them: the latest decided for
  // a frame not decided yet, the session file's before frame 0.
  std::vector<WindowPlace> shown_at(int frame) const;
  // A window's source ("picture", "mesh", ...), as the session file names it.
  const std::string& source_of(int id) const;

  // "windows: move 1 to 100,80 300x200 from frame 14", a line a change; empty without any.
  std::string summary() const;
  // OUT/windows.txt's text: frame k's WINDOWS line on line k (frames 1.. as decided; frame 0 is
  // the session file's).
  std::string windows() const;

 private:
  // Changes window `id` now (move to `r`, raise, close); empty when done, else why not.
  std::string apply(std::string_view verb, int id, const Rect& r);

  std::vector<WindowPlace> now_;      // back to front
  std::vector<int> ids_;              // every window of the session, closed ones too
  std::vector<std::string> sources_;  // by the same index as ids_
  std::vector<std::string> lines_;    // by frame decided so far, from frame 0
  std::vector<std::string> pending_;  // commands taken since the last frame decided
  std::vector<std::string> changes_;  // "move 1 to ... from frame 14"
};

}  // namespace l2
