// `movie`: a movie (any format FFmpeg reads) played by its own clock, the whole movie frame
// fitted to the canvas (picture_view.hpp): application frame k shows the movie at k / rate
// seconds, frames dropped or repeated as the rates differ; with rate 0, movie frame k is
// application frame k (exact, for tests). Every pipeserver decodes the movie itself and picks
// the same frame for an application frame from the frame number alone, so they never disagree.
#include "image/movie_file.hpp"
#include "scene_common.hpp"
#include "source_fill.hpp"

#include <cmath>
#include <cstring>

namespace l2::detail {

namespace {

class MovieScene : public Scene {
 public:
  MovieScene(const std::filesystem::path& file, double rate, SourceFit fit)
      : movie_(file), rate_(rate), fps_(movie_.frames_per_second()), fit_(fit) {
    lit_ = false;
    shown_ = &movie_.frame(0);  // a movie without frames is refused here, before the run
  }
  const char* name() const override { return "movie"; }

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override {
    const RgbImage& frame = *shown_;
    fill_from_source(
        movie_view(frame.width(), frame.height(), canvas, fit_), frame.width(), frame.height(),
        canvas, on_canvas,
        [&frame](int y, int x_begin, int x_end, std::uint8_t* out) {
          std::memcpy(out, frame.row(y).data() + 3 * x_begin,
                      static_cast<std::size_t>(x_end - x_begin) * 3);
        },
        rgb);
    return true;
  }

 protected:
  void animate(int frame) override { shown_ = &movie_.frame(movie_frame(frame)); }

 private:
  // A movie whose container gives no rate is played frame for frame.
  long movie_frame(int frame) const {
    if (rate_ <= 0 || fps_ <= 0) return frame;
    return static_cast<long>(std::floor(frame * fps_ / rate_ + 1e-9));
  }

  MovieFile movie_;
  double rate_, fps_;
  SourceFit fit_;
  const RgbImage* shown_ = nullptr;
};

}  // namespace

std::unique_ptr<Scene> make_movie_scene(const std::filesystem::path& file, double rate,
                                        SourceFit fit) {
  return std::make_unique<MovieScene>(file, rate, fit);
}

}  // namespace l2::detail
