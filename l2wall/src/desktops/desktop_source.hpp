// Where the coordinator's desktop comes from (--scene vnc, docs/vnc.md): the edge of the run
// that talks to a desktop server. The one real source is an RFB (VNC) connection
// (vnc_desktop.cpp); what the run does with the pixels is DesktopFrames', without I/O.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "desktop_frames.hpp"

namespace l2 {

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

// "HOST:DISPLAY" or "HOST::PORT" as host and port; throws DesktopError for anything else.
std::pair<std::string, int> vnc_endpoint(const std::string& address);

}  // namespace l2
