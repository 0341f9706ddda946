// `movie`: frame k of a movie (any format FFmpeg reads) is application frame k, the whole movie
// frame fitted to the canvas (picture_view.hpp). Every pipeserver decodes the movie itself, in
// step with the frame numbers, and shows its tiles' part of the frame.
#include "image/movie_file.hpp"
#include "scene_common.hpp"
#include "source_fill.hpp"

#include <cstring>

namespace l2::detail {

namespace {

class MovieScene : public Scene {
 public:
  explicit MovieScene(const std::filesystem::path& file) : movie_(file) {
    lit_ = false;
    shown_ = &movie_.frame(0);  // a movie without frames is refused here, before the run
  }
  const char* name() const override { return "movie"; }

  bool fill_tile(const Canvas& canvas, const Rect& on_canvas, RgbImage& rgb) const override {
    const RgbImage& frame = *shown_;
    fill_from_source(
        movie_view(frame.width(), frame.height(), canvas), frame.width(), frame.height(), canvas,
        on_canvas,
        [&frame](int y, int x_begin, int x_end, std::uint8_t* out) {
          std::memcpy(out, frame.row(y).data() + 3 * x_begin,
                      static_cast<std::size_t>(x_end - x_begin) * 3);
        },
        rgb);
    return true;
  }

 protected:
  void animate(int frame) override { shown_ = &movie_.frame(frame); }

 private:
  MovieFile movie_;
  const RgbImage* shown_ = nullptr;
};

}  // namespace

std::unique_ptr<Scene> make_movie_scene(const std::filesystem::path& file) {
  return std::make_unique<MovieScene>(file);
}

}  // namespace l2::detail
