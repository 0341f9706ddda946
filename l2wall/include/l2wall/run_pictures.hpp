// The pictures a live run writes: a frame's displays (saved frames, the displays after a fault)
// and, when the two paths disagree, both pictures of the display and where they differ.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "image/rgb_image.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

using DisplayPictures = std::function<const RgbImage&(int display)>;

// DIR/display-<id><suffix>.png for every display of the wall and DIR/wall<suffix>.png. A
// display whose picture is empty (its process is gone, over MPI) is not written, nor then the
// wall picture: returns those displays' ids.
std::vector<int> write_display_pictures(const std::filesystem::path& dir, const Wall& wall,
                                        const DisplayPictures& display,
                                        const std::string& suffix = "");

// --path both --compare: every display of `frame` must be identical byte for byte on the DVI
// path and the vizserver path. On the first that is not, writes
// OUT/mismatch-frame-<k>/display-<id>-{dvi,vizserver,diff}.png and throws RunFault.
// `tamper_display_0` (fault injection) flips one pixel of the vizserver's display 0 first.
// Returns the number of displays compared.
int compare_paths(int frame, const Wall& wall, const DisplayPictures& via_dvi,
                  const DisplayPictures& via_viz, bool tamper_display_0,
                  const std::filesystem::path& out);

// The files in `dir`, by name ("display-0.png, display-1.png"); empty when none (or no `dir`).
// After a picture could not be written: those written before it, each whole.
std::string pictures_in(const std::filesystem::path& dir);

// Removes the pictures an earlier run into `out` left: frame-<k>/, mismatch-frame-<k>/ and
// fault/, which would stand beside this run's as if it had made them (a passing run next to an
// old fault/). Only folders named as a run names them; screenshots and anything else stay.
void remove_earlier_pictures(const std::filesystem::path& out);

}  // namespace l2
