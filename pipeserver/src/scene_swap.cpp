// `swap`: no geometry, every tile cleared to a colour of the frame number. It costs what a
// program that only calls SwapBuffers costs (WireGL's figure 9), yet each frame stays checkable.
#include "scene_common.hpp"

namespace l2::detail {

namespace {

class SwapScene : public Scene {
 public:
  SwapScene() { lit_ = false; }
  const char* name() const override { return "swap"; }

 protected:
  void animate(int frame) override {
    // Steps that are odd, so consecutive frames differ in every channel and the colour repeats
    // only every 256 frames; a byte over 255 clears to exactly that byte.
    const auto channel = [frame](int step, int base) {
      return static_cast<float>((base + step * frame) & 0xFF) / 255.0f;
    };
    clear_colour_ = {channel(37, 64), channel(101, 128), channel(173, 192)};
  }
};

}  // namespace

std::unique_ptr<Scene> make_swap_scene() {
  auto s = std::make_unique<SwapScene>();
  s->set_frame(0);
  return s;
}

}  // namespace l2::detail
