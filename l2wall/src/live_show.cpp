#include "l2wall/live_show.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "command_line/printable.hpp"
#include "image/folders.hpp"

namespace l2 {

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

// How often keys() looks for events: often enough for a key to feel immediate, rarely enough
// that a run at --refresh 0 does not spend its time asking the X server.
constexpr auto kLookEvery = 5ms;
constexpr auto kPausedPoll = 10ms;

}  // namespace

LiveShow::LiveShow(const RunOptions& o, const Wall& wall)
    : mode_(o.show),
      out_(o.out),
      readback_(o.show_readback),
      progress_(o.progress),
      planned_(o.frames) {
  const std::optional<ShowMode> mode = parse_show_mode(o.show);
  if (!mode) throw std::invalid_argument("--show: expected window or monitors, got " + o.show);
  if (!runs_dvi(o.path)) {
    throw std::invalid_argument(
        "--show needs the DVI path (--path dvi or both): on the vizserver path alone the "
        "compositing server paces the pipeservers, so there is no refresh to show or to pause");
  }
  // Vsync paces a refresh-rate run like a real display; --refresh 0 asks for full speed.
  presenter_ = open_presenter(*mode, wall, {.vsync = o.refresh_hz > 0, .title = title(wall)});
  for (const std::string& note : presenter_->notes()) std::cout << "--show: " << note << "\n";
  images_.resize(wall.displays.size());
}

LiveShow::~LiveShow() = default;

std::string LiveShow::title(const Wall& wall) {
  return wall.name.empty() ? std::string("l2wall") : "l2wall - " + printable(wall.name);
}

void LiveShow::show(int frame, long latency_frames,
                    const std::function<const RgbImage&(int)>& display) {
  for (std::size_t d = 0; d < images_.size(); ++d) images_[d] = display(static_cast<int>(d));
  meter_.tick(Clock::now());
  info_ = {frame, meter_.fps(), static_cast<int>(latency_frames), paused_};
  presenter_->present(info_, images_);
  ++presented_;
  if (!readback_.empty()) {
    // Verification aid: what the X server shows, written next to the run's own pictures.
    const auto dir = readback_ / fmt::format("frame-{}", frame);
    make_folders(dir);
    save_screenshots(*presenter_, dir, "");
  }
}

LiveShow::Keys LiveShow::keys(const std::function<void()>& while_paused) {
  Keys keys;
  const auto now = Clock::now();
  if (now - last_look_ < kLookEvery) {
    keys.quit = quit_;
    return keys;
  }
  last_look_ = now;
  for (UserAction a = presenter_->poll_events(); a != UserAction::None;
       a = presenter_->poll_events())
    act(a);
  if (paused_ && !quit_) {
    const auto t0 = Clock::now();
    while (paused_ && !quit_) {
      std::this_thread::sleep_for(kPausedPoll);
      while_paused();
      for (UserAction a = presenter_->poll_events(); a != UserAction::None;
           a = presenter_->poll_events())
        act(a);
    }
    keys.paused = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t0);
    paused_total_ += keys.paused;
    meter_ = FpsMeter();  // the rate after a pause starts afresh
  }
  keys.quit = quit_;
  return keys;
}

void LiveShow::act(UserAction action) {
  switch (action) {
    case UserAction::PauseToggled:
      toggle_pause();
      break;
    case UserAction::Screenshot:
      screenshot();
      break;
    case UserAction::Quit:
      if (!quit_) {
        say(presented_ > 0 ? fmt::format("quit: the run ends after frame {}", info_.frame)
                           : std::string("quit: the run ends after its first frame"));
      }
      quit_ = true;
      break;
    case UserAction::None:
      break;
  }
}

void LiveShow::toggle_pause() {
  paused_ = !paused_;
  if (paused_) {
    ++pauses_;
    say(fmt::format("paused {} (the pipeservers wait for READY); space resumes", at_frame()));
  } else {
    say(fmt::format("resumed {}", at_frame()));
  }
  info_.paused = paused_;
  info_.fps = paused_ ? 0.0 : info_.fps;
  presenter_->present(info_, images_);  // the overlay says "paused"
}

std::string LiveShow::at_frame() const {
  return presented_ > 0 ? fmt::format("at frame {}", info_.frame) : "before the first frame";
}

void LiveShow::screenshot() {
  if (presented_ == 0) {
    say("screenshot: nothing on the displays yet");
    return;
  }
  const auto dir = out_ / "screenshots";
  make_folders(dir);
  const auto files = save_screenshots(*presenter_, dir, fmt::format("frame-{}-", info_.frame));
  ++screenshots_;
  say(fmt::format("screenshot of frame {}: {} files, {}/frame-{}-display-<d>.png", info_.frame,
                  files.size(), dir.string(), info_.frame));
}

void LiveShow::say(const std::string& line) const {
  // After the progress line (which ends with \r), on a line of its own.
  std::fprintf(stderr, "%sl2wall: %s\n", progress_ ? "\n" : "", line.c_str());
  std::fflush(stderr);
}

std::string LiveShow::summary(int frames_shown) const {
  std::string line = fmt::format("show: {}, {} frames presented", mode_, presented_);
  if (pauses_ > 0)
    line +=
        fmt::format(", paused {} time{} ({:.1f} s, not counted in the fps)", pauses_,
                    pauses_ == 1 ? "" : "s", std::chrono::duration<double>(paused_total_).count());
  if (screenshots_ > 0)
    line += fmt::format(", {} screenshot{} in {}", screenshots_, screenshots_ == 1 ? "" : "s",
                        (out_ / "screenshots").string());
  if (quit_ && frames_shown < planned_)
    line += fmt::format(", quit by the user after frame {} of {}", frames_shown - 1, planned_);
  return line + "\n";
}

}  // namespace l2
