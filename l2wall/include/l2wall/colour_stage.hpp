// Colour matching where a display's pixels leave the wall (docs/wall-file.md, "Colour
// matching"): each display's table (Display::colour) applied to the pictures a display path
// hands out, so what is shown (--show), saved (frame-<k>/, fault/), compared (--path both
// --compare) and published (--http) is the matched picture.
//
// Both display paths call this one class on their pictures (DviPath, VizPath), and nothing
// before it sees the colour: the emulator's front buffers and the compositing server's frames
// stay as routed, because the DVI path reads the frame stamps back from the front buffers
// (board_column.hpp) and the verifier judges routing on reassembled pixels, neither of which a
// table may change. Applying it where the pictures leave both paths also makes --compare check
// the matched bytes on both sides with the same code.
//
// Owns: each display's table and the matched picture it last handed out. A display whose table
// changes nothing hands out the path's own picture, at no cost.
#pragma once

#include <map>
#include <memory>

#include "image/colour_table.hpp"
#include "l2wall/run_pictures.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class ColourStage {
 public:
  ColourStage() = default;  // a wall without colour matching
  explicit ColourStage(const Wall& wall);

  // Whether any display changes its pixels.
  bool applies() const { return tables_ != nullptr; }
  // `raw`'s pictures as the displays show them. A picture handed out stays valid until the same
  // display is asked again through any pictures of this stage (and while `raw`'s is). An empty
  // picture (a display lost with its rank) stays empty.
  DisplayPictures apply(DisplayPictures raw) const;

 private:
  struct Matched {
    ColourTable table;
    RgbImage picture;
  };
  // By display id, only the displays whose table changes something. Shared, so the pictures
  // handed out by a const path can be written, and outlive a moved stage.
  std::shared_ptr<std::map<int, Matched>> tables_;
};

}  // namespace l2
