// Where the coordinator's desktops come from (--scene vnc, docs/vnc.md; a session's shares,
// control_page/README.md): the edge of the run that takes in a desktop's pixels. The sources are
// an RFB (VNC) connection (vnc_desktop.cpp) and a screen a browser shares through the control
// page (share_desktop.cpp); what the run does with the pixels is DesktopFrames', without I/O.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "desktop_frames.hpp"

namespace l2 {

class ShareInbox;  // control_page/share_inbox.hpp

class DesktopSource {
 public:
  virtual ~DesktopSource() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Takes in what the server sent since the last call, waiting up to `wait` for something:
  // writes it into frames.live() and tells frames what changed. Only whole updates: never half
  // of one. Throws DesktopError when the server is gone or the desktop changed size.
  virtual void take_updates(DesktopFrames& frames, std::chrono::milliseconds wait) = 0;
};

// An RFB connection to "HOST:DISPLAY" (port 5900 + DISPLAY) or "HOST::PORT", asking for
// incremental updates; `password_file`: the file `vncpasswd -f` writes, empty for none. Throws
// DesktopError in one line: the server cannot be reached, wants a password, refused it.
std::unique_ptr<DesktopSource> connect_vnc(const std::string& address,
                                           const std::string& password_file);

// The screen shared into window `window` through the control page: frames of width x height,
// taken from `inbox` as they come (share_desktop.cpp).
std::unique_ptr<DesktopSource> share_source(std::shared_ptr<ShareInbox> inbox, int window,
                                            int width, int height);

// "HOST:DISPLAY" or "HOST::PORT" as host and port; throws DesktopError for anything else.
std::pair<std::string, int> vnc_endpoint(const std::string& address);

}  // namespace l2
