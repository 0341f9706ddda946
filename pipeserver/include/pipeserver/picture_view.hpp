// Where a picture or a movie frame (the source) lies on the canvas, frame by frame. Canvas
// pixel (X, Y) shows source pixel
//   (floor(centre_x + (X + 0.5 - W / 2) * scale_x), floor(centre_y + (Y + 0.5 - H / 2) * scale_y))
// for a W x H canvas, rows top to bottom in both, and black where that lies outside the
// source: nearest sampling, so every pixel shown is one of the source's, on every tile alike.
//
// MIP levels: a picture whose file holds levels (level L about 2^-L of the picture's sides,
// each pixel the average of the 2^L x 2^L picture pixels under it) is read, zoomed out, at
// level L = the largest L with 2^L <= min(scale_x, scale_y), at most its last level: the
// coarsest level whose pixels are no larger than a canvas pixel on either axis, so a line one
// picture pixel wide stays on the canvas (averaged into its level's pixels) instead of falling
// between the pixels nearest sampling picks. Canvas pixel (X, Y) then shows level-L pixel
//   (min(floor(sx / 2^L), level width - 1), min(floor(sy / 2^L), level height - 1))
// for (sx, sy) the picture pixel the formula above gives, and black where that lies outside
// the picture: the same nearest sampling, from the same numbers, so a pixel still depends only
// on its canvas position and the view, never on the tile or the pipeserver drawing it.
#pragma once

#include <optional>
#include <string_view>

#include "pipeserver/camera.hpp"

namespace l2 {

struct SourceView {
  double centre_x = 0, centre_y = 0;  // the source point at the canvas's centre
  double scale_x = 1, scale_y = 1;    // source pixels per canvas pixel, across and down
};

// How a picture or movie frame is laid on the canvas (--fit): all of it in view, black bars on
// two sides (fit); the canvas covered, the source cropped on two sides (fill); both axes
// scaled apart to cover the canvas exactly (stretch); or one source pixel per canvas pixel
// (1:1, a session's windows: the source's top-left pixel at the canvas's top-left).
enum class SourceFit { Fit, Fill, Stretch, OneToOne };
// "fit", "fill", "stretch", "1:1"
std::optional<SourceFit> parse_source_fit(std::string_view name);

// Frames a zoom takes to go from the picture's cover view to 1:1 and back.
inline constexpr int kPictureZoomPeriod = 600;

// The picture scene: frame 0 shows the picture laid on the canvas as `fit` says (by default as
// large as it covers the canvas: all of its width or all of its height), centred; it zooms in
// to one picture pixel per canvas pixel at frame kPictureZoomPeriod / 2 and out again, panning
// meanwhile along a Lissajous path that keeps as much of the canvas covered as frame 0 did. A
// picture smaller than the canvas stays at its frame-0 view.
SourceView picture_view(int frame, int source_width, int source_height, const Canvas& canvas,
                        SourceFit fit = SourceFit::Fill);

// A fixed view of the picture instead of the animated path (--pan X,Y, --zoom Z on pipeserver
// and l2wall run): picture pixel (X, Y) at the canvas's centre (the picture's centre when not
// given), Z canvas pixels per picture pixel on both axes (scale 1 / Z: 1 is 1:1, 0.25 shows 4x4
// picture pixels in a canvas pixel, 2 magnifies each to 2x2; when not given, the scale of
// frame 0 as `fit` lays it), at every frame.
struct FixedView {
  std::optional<double> x, y;
  double zoom = 0;  // 0: the fit's
};
SourceView fixed_view(const FixedView& fixed, int source_width, int source_height,
                      const Canvas& canvas, SourceFit fit = SourceFit::Fill);
// "X,Y" (two numbers: picture pixels, fractions allowed) into `fixed`; false when it is not.
bool parse_pan(std::string_view text, FixedView& fixed);

// The movie scene, and a still picture in a session's window: the whole frame laid on the canvas
// as `fit` says (by default as large as it fits, centred, black bars on the other sides).
SourceView movie_view(int source_width, int source_height, const Canvas& canvas,
                      SourceFit fit = SourceFit::Fit);

// The source index canvas pixel `x` shows along one axis of a canvas `size` wide (the formula
// above); out of [0, source size) it shows none.
long source_index(double centre, double scale, int size, int x);
// The MIP level a view samples from a picture of `levels` levels (the rule above): 0 when
// the view is at 1:1 or closer, or the picture has no levels.
int mip_level(const SourceView& view, int levels);
// The pixel of a level `level_size` wide that level-0 index `index` of a source `size` wide
// falls in at level `level` (the rule above); -1 when the index lies outside the source.
long level_index(long index, int size, int level, int level_size);

// The source pixels `on_canvas` shows, clipped to the source (empty: none): all that nearest
// sampling reads for it, so what a desktop's coordinator sends a pipeserver for a tile.
Rect sampled_source(const SourceView& view, int source_width, int source_height,
                    const Canvas& canvas, const Rect& on_canvas);

}  // namespace l2
