#include "column_show.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <utility>

#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "l2wall/live_show.hpp"

namespace l2 {
namespace {

Wall own_displays(const Wall& wall, const std::vector<int>& ids) {
  Wall own = wall;
  own.displays.clear();
  for (const int id : ids) {
    const auto it = std::find_if(wall.displays.begin(), wall.displays.end(),
                                 [id](const Display& d) { return d.id == id; });
    if (it != wall.displays.end()) own.displays.push_back(*it);
  }
  return own;
}

}  // namespace

ColumnShow::ColumnShow(const Wall& wall, const std::vector<int>& ids, bool vsync,
                       std::filesystem::path readback)
    : wall_(own_displays(wall, ids)), readback_(std::move(readback)) {
  presenter_ =
      open_presenter(ShowMode::Monitors, wall_, {.vsync = vsync, .title = LiveShow::title(wall)});
  for (const std::string& note : presenter_->notes()) std::cout << "--show: " << note << "\n";
  images_.resize(wall_.displays.size());
}

void ColumnShow::present(int frame, const std::function<const RgbImage&(int)>& display) {
  for (std::size_t d = 0; d < images_.size(); ++d) images_[d] = display(wall_.displays[d].id);
  presenter_->present({frame, 0.0, 1, false}, images_);
  // Keys are the one-machine run's; the events are still taken so the windows stay responsive.
  while (presenter_->poll_events() != UserAction::None) {
  }
  if (readback_.empty() || frame < 0) return;
  // Verification aid: what this machine's X server shows, named as the run's own pictures.
  const auto dir = readback_ / fmt::format("frame-{}", frame);
  make_folders(dir);
  const std::vector<RgbImage> back = presenter_->read_back();
  for (std::size_t d = 0; d < back.size(); ++d)
    write_png(dir / fmt::format("display-{}.png", wall_.displays[d].id), back[d]);
}

}  // namespace l2
