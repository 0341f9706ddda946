// One GLFW window with its own legacy-GL (2.1) context: display images uploaded as textures with
// GL_NEAREST filtering and drawn as quads on integer pixel edges, so an image drawn at its own
// size lands pixel for pixel; read-back asks the X server for the window's pixels, which is what
// the screen shows (Mesa's software GL reads its front buffer as black under Xvfb).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "displays/wall_presenter.hpp"
#include "image/rgb_image.hpp"
#include "tilelayout/geometry.hpp"

struct GLFWwindow;
struct GLFWmonitor;

namespace l2 {

struct WindowSpec {
  int width = 0, height = 0;
  std::string title;
  GLFWmonitor* fullscreen_on = nullptr;  // nullptr: an ordinary window
  int x = -1, y = -1;                    // position of an ordinary window; -1: leave it
  int swap_interval = 1;                 // 1: wait for vertical blank, 0: swap at once
};

class GlWindow {
 public:
  explicit GlWindow(const WindowSpec& spec);  // throws DisplayError
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  int framebuffer_width() const;
  int framebuffer_height() const;

  // Makes the context current, sets a top-left pixel projection and clears to `background`.
  void begin_frame(Rgb background);
  // Draws `image` into `dst` (window pixels) through texture `slot`, re-uploading it each frame.
  void draw_image(std::size_t slot, const RgbImage& image, const Rect& dst);
  // Finishes drawing so that swaps of a group can follow back to back.
  void finish_drawing();
  void swap();

  // The window's pixels as the X server holds them (what is on screen), rows top to bottom;
  // `area` in window pixels. Throws DisplayError when the window is not fully on screen.
  RgbImage read_shown(const Rect& area);
  RgbImage read_shown();

  // The next key / close action this window received; None when there is none.
  UserAction next_action();

 private:
  static void on_char(GLFWwindow* w, unsigned int codepoint);
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_close(GLFWwindow* w);
  void push(UserAction action) { actions_.push_back(action); }

  struct Texture {
    unsigned id = 0;
    int width = 0, height = 0;
  };

  GLFWwindow* window_ = nullptr;
  std::vector<Texture> textures_;
  std::deque<UserAction> actions_;
};

}  // namespace l2
