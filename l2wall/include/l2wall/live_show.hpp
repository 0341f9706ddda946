// `l2wall run --show window|monitors`: the run's output displays on screen after every swap,
// and the keys of its windows. Space pauses the run: it takes nothing in and sends no READY, so
// the pipeservers wait as they would for a real Lightning-2. s saves what the screens show of every
// display into OUT/screenshots/. q, Esc or closing a window end the run as after its last frame.
// The run calls show() after each swap and keys() once per refresh; everything else is here.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "displays/overlay.hpp"
#include "displays/wall_presenter.hpp"
#include "image/rgb_image.hpp"
#include "l2wall/live_run.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class LiveShow {
 public:
  // Opens the window(s) for o.show. Throws DisplayError (one line: no screen, too few
  // monitors, ...) and std::invalid_argument for a bad mode or the vizserver-only path.
  LiveShow(const RunOptions& o, const Wall& wall);
  ~LiveShow();
  LiveShow(const LiveShow&) = delete;
  LiveShow& operator=(const LiveShow&) = delete;

  // The windows' title ("l2wall - <wall name>"; fullscreen ones add " - display <id>").
  static std::string title(const Wall& wall);

  // After a swap: shows `frame` (display(id): display id's picture) with the frames per second
  // and the measured latency in the overlay line.
  void show(int frame, long latency_frames, const std::function<const RgbImage&(int)>& display);

  struct Keys {
    bool quit = false;                    // the user asked to end the run (stays set)
    std::chrono::milliseconds paused{0};  // time spent paused in this call
  };
  // Acts on the keys pressed since the last look (it looks at most every few ms). While paused
  // it returns only on resume or quit, calling `while_paused` every 10 ms meanwhile so the run
  // keeps watching its pipeservers and answering their SYNC? requests.
  Keys keys(const std::function<void()>& while_paused);

  // One line for the summary: mode, frames presented, pauses, screenshots, how the run ended.
  std::string summary(int frames_shown) const;

 private:
  void act(UserAction action);
  void toggle_pause();
  void screenshot();
  void say(const std::string& line) const;
  std::string at_frame() const;  // "at frame 12", or "before the first frame"

  std::string mode_;
  std::filesystem::path out_, readback_;
  bool progress_ = true;
  int planned_ = 0;  // --frames
  std::unique_ptr<WallPresenter> presenter_;
  std::vector<RgbImage> images_;  // the displays as last shown
  FrameInfo info_;
  FpsMeter meter_;
  bool paused_ = false, quit_ = false;
  int presented_ = 0, pauses_ = 0, screenshots_ = 0;
  std::chrono::milliseconds paused_total_{0};
  std::chrono::steady_clock::time_point last_look_{};
};

}  // namespace l2
