// `--show monitors` on a board column rank: the column's own displays, each fullscreen on the
// monitor its wall-file `monitor` names, on the X display of the machine the rank runs on (its
// DISPLAY). The one-machine presenter (displays/) does the showing; keys are not read here, as
// pause and quit are the one-machine run's (the coordinator paces an MPI run).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "displays/wall_presenter.hpp"
#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class ColumnShow {
 public:
  // `ids`: the column's display ids. `readback`: empty, or the --show-readback folder. Throws
  // DisplayError (one line) as the presenter does.
  ColumnShow(const Wall& wall, const std::vector<int>& ids, bool vsync,
             std::filesystem::path readback);

  // After a swap: shows the displays' pictures (display(id): display id's); `frame` (the
  // oldest frame they show, -1 for none yet) names the readback folder,
  // DIR/frame-<k>/display-<id>.png.
  void present(int frame, const std::function<const RgbImage&(int)>& display);

 private:
  Wall wall_;  // the column's displays only
  std::filesystem::path readback_;
  std::unique_ptr<WallPresenter> presenter_;
  std::vector<RgbImage> images_;
};

}  // namespace l2
