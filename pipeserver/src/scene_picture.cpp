// `picture`: a still picture, of any size and format OpenImageIO reads, panned and zoomed
// across the canvas (picture_view.hpp), or at a fixed view (--pan, --zoom). Each tile reads
// only the rows and columns it shows, through an image cache of bounded size, so a pipeserver
// never holds the whole picture; zoomed out, from the file's MIP level picture_view.hpp names,
// when it has levels. In a session's window the picture stays still, laid on the window as its
// fit says.
#include "image/picture_regions.hpp"
#include "image/tiled_copy.hpp"
#include "pipeserver/picture_cache.hpp"
#include "scene_common.hpp"
#include "source_fill.hpp"

namespace l2::detail {

namespace {

// The cache's limit: the one given, else the machine's default for a pipeserver alone. A
// picture stored as scanlines past it is read from its tiled copy (image/tiled_copy.hpp).
double cache_limit(double cache_mb) {
  return cache_mb > 0 ? cache_mb : default_picture_cache_mb(physical_memory_mb(), 1);
}

class PictureScene : public Scene {
 public:
  PictureScene(const std::filesystem::path& file, SourceFit fit, double cache_mb, bool still,
               std::optional<FixedView> fixed)
      : picture_(picture_to_read(file, cache_limit(cache_mb)), cache_limit(cache_mb)),
        fit_(fit),
        still_(still),
        fixed_(fixed) {
    lit_ = false;
  }
  const char* name() const override { return "picture"; }

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override {
    const SourceView view = this->view(canvas);
    const int level = mip_level(view, picture_.levels());
    fill_from_source(
        view, picture_.width(), picture_.height(),
        {level, picture_.width(level), picture_.height(level)}, canvas, on_canvas,
        [this, level](int y, int x_begin, int x_end, std::uint8_t* out) {
          picture_.read_row(level, y, x_begin, x_end, out);
        },
        rgb);
    return true;
  }

 protected:
  void animate(int frame) override { frame_ = frame; }

 private:
  SourceView view(const Canvas& canvas) const {
    const int w = picture_.width(), h = picture_.height();
    if (still_) return movie_view(w, h, canvas, fit_);
    if (fixed_) return fixed_view(*fixed_, w, h, canvas, fit_);
    return picture_view(frame_, w, h, canvas, fit_);
  }

  PictureRegions picture_;
  SourceFit fit_;
  bool still_;
  std::optional<FixedView> fixed_;
  int frame_ = 0;
};

}  // namespace

std::unique_ptr<Scene> make_picture_scene(const std::filesystem::path& file, SourceFit fit,
                                          double cache_mb, bool still,
                                          std::optional<FixedView> fixed) {
  return std::make_unique<PictureScene>(file, fit, cache_mb, still, fixed);
}

}  // namespace l2::detail
