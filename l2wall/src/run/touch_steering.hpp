#pragma once

#include <memory>
#include <string>
#include <vector>

#include "run_windows.hpp"
#include "tilelayout/wall.hpp"
#include "touch/gestures.hpp"
#include "touch/tuio_receiver.hpp"

namespace l2 {

// Touch steering (--tuio): a touch frame's or pointer's TUIO cursors, read at each step of the
// frame loop, turned into window commands by the gestures on the windows the displays show. It
// owns the TUIO socket and the gestures' state; the commands it gives are issued by the frame
// loop through the run's windows, as --window-stdin's lines are, so every display switches in
// the same frame. Without --tuio it opens nothing and gives nothing.
class TouchSteering {
 public:
  // Opens the socket of --tuio [ADDR:]PORT and says where it listens; throws NetError in one
  // line when it cannot. Nothing without --tuio.
  void start(const std::string& address, const Wall& wall);
  // The commands of the cursor frames waiting, as the windows of `frame` (the last on the
  // displays) placed them: the last move of a window only, since a frame shows one place.
  std::vector<std::string> commands(const RunWindows& windows, int frame);
  // "touch: 3 gestures (1 tap, 1 drag, 1 pinch), 2 windows moved, 1 raised; 0 packets, 0
  // messages dropped\n"; empty without --tuio.
  std::string summary() const;

 private:
  std::unique_ptr<TuioReceiver> receiver_;
  std::unique_ptr<Gestures> gestures_;
};

}  // namespace l2
