// A private Xvfb server for one test: started as a child process on a display number it picks
// itself (-displayfd, so parallel tests never collide), killed and reaped at the end.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace l2::testing {

class XvfbServer {
 public:
  // True when an Xvfb executable is on PATH; tests skip without it.
  static bool installed();

  // Starts `Xvfb -screen 0 <width>x<height>x24 -nolisten tcp` and waits until it accepts
  // clients, then points DISPLAY at it. Throws std::runtime_error when it does not start.
  XvfbServer(int width, int height);
  // Any X server that reports its display on -displayfd (Xvnc too): `program` (on PATH) with
  // `args` after -displayfd. DISPLAY is left as it was.
  XvfbServer(const std::string& program, const std::vector<std::string>& args);
  ~XvfbServer();
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;

  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace l2::testing
