// A vnc run's desktop on the coordinator (docs/vnc.md): the one RFB connection, and the
// answers to every pipeserver's WANT on its windows channel, each pipeserver sent only the
// part of the frame's frozen desktop its tiles show (desktop_frames.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "desktop_frames.hpp"
#include "desktop_source.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

class LiveDesktop {
 public:
  // Waits for the server's first picture; throws DesktopError when none comes.
  LiveDesktop(std::unique_ptr<DesktopSource> source, const TileLayout& layout);

  // Takes in the server's updates and answers every WANT waiting. Throws RunFault when the
  // server is gone or the desktop changed size (naming the server), or for a line that is not
  // a WANT.
  void serve(PipeserverSet& pipeservers);

  // Takes in the server's updates, waiting for none. Throws RunFault as serve() does.
  void take_updates();
  // The lines that answer `pipeserver`'s WANT for `frame`, of the frame's one frozen desktop:
  // the parts of it in `regions` (desktop pixels) that changed since it was last sent them
  // (DesktopFrames::answer). A session's desktops ask with the regions its windows sample.
  std::vector<std::string> answer(int pipeserver, int frame, const std::vector<Rect>& regions) {
    return frames_.answer(pipeserver, frame, regions);
  }
  int width() const { return frames_.width(); }
  int height() const { return frames_.height(); }

  // "vnc: desktop 1300x980", for the summary.
  std::string summary() const;

 private:
  std::unique_ptr<DesktopSource> source_;
  DesktopFrames frames_;
  std::vector<std::vector<Rect>> tiles_;  // by pipeserver: its tiles' canvas rectangles
};

}  // namespace l2
