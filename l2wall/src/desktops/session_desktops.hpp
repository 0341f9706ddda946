// A session's desktops on the coordinator (docs/session-file.md, docs/vnc.md): its vnc windows'
// desktops, one RFB connection each (LiveDesktop), connected before any pipeserver starts, and
// its screens shared from the control page (session_shares.hpp), after them.
// A pipeserver's WANT for a frame is answered with the frame's WINDOWS line (live_windows.hpp)
// and then, for every desktop, its DESKTOP and RECT lines: of the one desktop state frozen for
// that frame, the parts the pipeserver's tiles sample through the windows shown in it, so no
// frame is torn and a moved window is drawn from the right pixels in the frame it moves in.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "balance/control_messages.hpp"
#include "desktop_regions.hpp"
#include "live_desktop.hpp"
#include "session_shares.hpp"
#include "tilelayout/session_file.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

class SessionDesktops {
 public:
  // An RFB connection to `address` with the password file (empty: none), as connect_vnc.
  using Connect = std::function<std::unique_ptr<DesktopSource>(const std::string& address,
                                                               const std::string& password_file)>;
  // Connects to every desktop the session's vnc windows show and waits for its first picture.
  // Throws DesktopError naming the first window of the desktop: "window 2: vnc ...".
  SessionDesktops(const Session& session, const TileLayout& layout, const Connect& connect);

  bool empty() const { return desktops_.empty() && shares_.slots() == 0; }
  // The session's shared screens, whose desktops follow the vnc ones in every answer.
  SessionShares& shares() { return shares_; }
  // Takes in every server's updates and every share's frames. Throws RunFault naming the window:
  // "window 2: vnc ...".
  void take_updates();
  // Every desktop's lines for `pipeserver`'s frame `frame`, in which `shown` are the windows.
  std::vector<std::string> answer(int pipeserver, int frame, const std::vector<WindowPlace>& shown);
  // "window 2: vnc: desktop 1300x980", a line a desktop.
  std::string summary() const;

 private:
  struct Desktop {
    std::string address, password_file;
    int first_window = 0;  // what its errors name
    std::vector<DesktopWindow> windows;
    std::unique_ptr<LiveDesktop> live;
  };
  std::vector<Desktop> desktops_;         // in the order of the session's windows, as pipeservers
  SessionShares shares_;                  // after the desktops, as pipeservers
  std::vector<std::vector<Rect>> tiles_;  // by pipeserver: its tiles' canvas rectangles
};

}  // namespace l2
