// A program's own scene (renderer.hpp): no geometry of ours; each tile is the program's drawing.
#include "pipeserver/renderer.hpp"

namespace l2 {

namespace {

class OwnScene : public Scene {
 public:
  explicit OwnScene(DrawTile draw) : draw_(std::move(draw)) { lit_ = false; }
  const char* name() const override { return "own"; }
  // The drawing may change matrices and state as it likes: the next tile starts as this one did.
  void draw_tile(const TileView& view) const override {
    gl().PushAttrib(GL_ALL_ATTRIB_BITS);
    gl().MatrixMode(GL_PROJECTION);
    gl().PushMatrix();
    gl().MatrixMode(GL_MODELVIEW);
    gl().PushMatrix();
    draw_(view);
    gl().MatrixMode(GL_PROJECTION);
    gl().PopMatrix();
    gl().MatrixMode(GL_MODELVIEW);
    gl().PopMatrix();
    gl().PopAttrib();
  }

 protected:
  void animate(int /*frame*/) override {}

 private:
  DrawTile draw_;
};

}  // namespace

std::unique_ptr<Scene> make_own_scene(DrawTile draw) {
  return std::make_unique<OwnScene>(std::move(draw));
}

int run_renderer(int argc, char** argv, DrawTile draw) {
  replace_scenes([draw = std::move(draw)] { return make_own_scene(draw); });
  return run_pipeserver(argc, argv);
}

}  // namespace l2
