#include "sequence_show.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <thread>

#include "image/folders.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kRowGap = 16;  // pixels between displays laid out in a row (--displays)

}  // namespace

Wall wall_to_show(const CommonOptions& o, const Setup& setup) {
  if (!o.wall.empty()) return load_wall(o.wall);
  Wall wall;
  wall.source = "--displays";  // names the wall in error messages
  int x = 0;
  for (const DisplaySpec& spec : setup.config.displays) {
    Display d;
    d.id = spec.id;
    d.width = spec.width;
    d.height = spec.height;
    d.canvas_x = x;
    d.swap_group = spec.swap_group;
    d.monitor = std::to_string(spec.id);
    x += spec.width + kRowGap;
    wall.canvas_height = std::max(wall.canvas_height, spec.height);
    wall.displays.push_back(d);
  }
  wall.canvas_width = std::max(1, x - kRowGap);
  return wall;
}

SequenceShow::SequenceShow(const CommonOptions& o, const Setup& setup, const ShowOptions& show)
    : wall_(wall_to_show(o, setup)), options_(show), out_(o.out) {
  const std::optional<ShowMode> mode = parse_show_mode(show.mode);
  if (!mode) throw std::invalid_argument("--show: expected window or monitors, got " + show.mode);
  if (options_.refresh_hz < 0) options_.refresh_hz = o.wall.empty() ? 60.0 : wall_.refresh_hz;
  if (options_.refresh_hz > 0) {
    period_ = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(1.0 / options_.refresh_hz));
  }
  presenter_ = open_presenter(
      *mode, wall_, {.vsync = options_.refresh_hz > 0, .title = "lightning2_emu sequence"});
  images_.resize(wall_.displays.size());
  info_.latency_frames = 1;  // the emulator's rule (spec §6.3), not measured here
  next_ = Clock::now();
}

SequenceShow::~SequenceShow() = default;

bool SequenceShow::play(int t, const std::vector<const RgbImage*>& by_id) {
  for (std::size_t i = 0; i < images_.size(); ++i) {
    const RgbImage* shown = by_id.at(static_cast<std::size_t>(wall_.displays[i].id));
    if (!shown) throw std::logic_error("sequence --show: a wall display the emulator lacks");
    images_[i] = *shown;
  }
  meter_.tick(Clock::now());
  info_.frame = t;
  info_.fps = meter_.fps();
  presenter_->present(info_, images_);
  if (!options_.readback.empty()) {
    const auto dir = options_.readback / fmt::format("frame-{}", t);
    make_folders(dir);
    save_screenshots(*presenter_, dir, "");
  }
  wait_for_next_refresh();
  return !quit_;
}

// Until the next refresh is due (on a fixed grid; a late one is not made up) and for as long
// as the sequence is paused, the keys are what happens.
void SequenceShow::wait_for_next_refresh() {
  next_ += period_;
  for (;;) {
    for (UserAction a = presenter_->poll_events(); a != UserAction::None;
         a = presenter_->poll_events())
      act(a);
    const auto now = Clock::now();
    if (quit_ || (!paused_ && now >= next_)) break;
    std::this_thread::sleep_until(paused_ ? now + std::chrono::milliseconds(10)
                                          : std::min(next_, now + std::chrono::milliseconds(10)));
  }
  if (Clock::now() > next_ + period_) next_ = Clock::now();  // after a pause or a slow refresh
}

void SequenceShow::act(UserAction a) {
  switch (a) {
    case UserAction::PauseToggled:
      paused_ = !paused_;
      info_.paused = paused_;
      if (!paused_) meter_ = FpsMeter();
      presenter_->present(info_, images_);
      fmt::print(stderr, "lightning2_emu: {} at refresh {}\n", paused_ ? "paused" : "resumed",
                 info_.frame);
      break;
    case UserAction::Screenshot: {
      const auto dir = out_ / "screenshots";
      make_folders(dir);
      const auto files = save_screenshots(*presenter_, dir, fmt::format("frame-{}-", info_.frame));
      fmt::print(stderr, "lightning2_emu: screenshot of refresh {}: {} files in {}\n", info_.frame,
                 files.size(), dir.string());
      break;
    }
    case UserAction::Quit:
      if (!quit_) fmt::print(stderr, "lightning2_emu: quit at refresh {}\n", info_.frame);
      quit_ = true;
      break;
    case UserAction::None:
      break;
  }
}

}  // namespace l2
