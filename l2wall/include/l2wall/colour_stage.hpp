// The display stage: what a display does to its pixels where they leave the wall — its geometry
// warp (docs/wall-file.md, "Warping projected pictures"), its alpha and beta maps ("Alpha and
// beta maps"), edge blending of overlapping
// projectors ("Blending overlapping projectors") and colour matching ("Colour matching") —
// applied to the pictures a display path hands out, so what is shown (--show), saved
// (frame-<k>/, fault/), compared (--path both --compare) and published (--http) is the picture
// the display shows.
//
// Both display paths call this one class on their pictures (DviPath, VizPath), and nothing
// before it sees warp, blend or colour: the emulator's front buffers and the compositing server's
// frames stay as routed, because the DVI path reads the frame stamps back from the front buffers
// (board_column.hpp) and the verifier judges routing on reassembled pixels, neither of which a
// table may change. Applying it where the pictures leave both paths also makes --compare check
// the shown bytes on both sides with the same code.
//
// Blending is this class's, not a stage of its own beside it, because both are byte tables
// applied to the same pictures at the same place: a blended display's tables are its blend table
// for each weight composed with its colour table, so each pixel is looked up once. Blend comes
// first: the weights share out the picture's light as the content means it, and colour matching
// then corrects what each projector makes of the code values it is sent. The warp comes before
// both: it moves the frame's pixels to where the projector's lens and the screen put them, and the
// blend and colour tables are of the projector's own pixels, wherever their content came from.
// The alpha and beta maps come between the warp and the blend: they are the calibration's own
// weights and black level of the projector's pixels, a gain and an offset per pixel.
//
// Owns: each display's warp and level maps (shared with the wall), its tables (one, or one per
// blend weight with the weight of every pixel) and the picture it last handed out, with the frame
// it is of when the caller said: a frame's pictures are asked for by several users (saved,
// compared, published to the page), and the warp and tables pass over every pixel, so each
// display's picture of a frame is made once. A display whose warp and tables change nothing hands
// out the path's own picture, at no cost.
#pragma once

#include <map>
#include <memory>
#include <optional>

#include "image/colour_table.hpp"
#include "image/level_map.hpp"
#include "image/table_map.hpp"
#include "image/warp_map.hpp"
#include "l2wall/run_pictures.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class ColourStage {
 public:
  ColourStage() = default;  // a wall without colour matching or blending
  explicit ColourStage(const Wall& wall);

  // Whether any display changes its pixels.
  bool applies() const { return tables_ != nullptr; }
  // `raw`'s pictures as the displays show them. A picture handed out stays valid until the same
  // display is asked again through any pictures of this stage (and while `raw`'s is). An empty
  // picture (a display lost with its rank) stays empty. `frame`: the application frame `raw`
  // shows, where the caller knows it for every display; a display asked again for the same frame
  // gets the picture made the first time, without `raw`'s being read.
  DisplayPictures apply(DisplayPictures raw, std::optional<int> frame = std::nullopt) const;

 private:
  struct Matched {
    std::shared_ptr<const WarpMap> warp;     // none when it does not warp
    std::shared_ptr<const LevelMap> levels;  // its alpha and beta maps, when any
    bool colour = false;                     // whether `table` changes anything
    ColourTable table;                       // a display that does not blend: its colour table
    std::optional<TableMap> map;             // one that does: blend and colour, per pixel
    RgbImage picture;
    std::optional<int> frame;  // the frame `picture` is of, where its caller said
  };
  // By display id, only the displays whose tables change something. Shared, so the pictures
  // handed out by a const path can be written, and outlive a moved stage.
  std::shared_ptr<std::map<int, Matched>> tables_;
};

}  // namespace l2
