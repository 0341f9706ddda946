// A test's own client of the X server: finds a window by its title, reads its pixels and types
// keys through the XTEST extension. XTEST keys take the server's input path, as a keyboard's
// would (focus, timestamps, KeyPress then KeyRelease), so the program under test gets ordinary
// key events, not synthetic ones it could tell apart.
#pragma once

#include <chrono>
#include <string>

#include "image/rgb_image.hpp"

namespace l2::testing {

class XClient {
 public:
  // Connects to `display` (":N"). Throws std::runtime_error when it cannot, or when the server
  // lacks the XTEST extension.
  explicit XClient(const std::string& display);
  ~XClient();
  XClient(const XClient&) = delete;
  XClient& operator=(const XClient&) = delete;

  // A top-level window whose title (WM_NAME) is `title`, once it is mapped; 0 when none
  // appeared within `timeout`.
  unsigned long wait_for_window(const std::string& title, std::chrono::milliseconds timeout);

  // Gives `window` the keyboard focus (what a click on it would do) and presses and releases
  // `key`, an X keysym name ("space", "s", "q", "Escape"). Throws for an unknown key name.
  void type(unsigned long window, const std::string& key);

  // The pixels of `window` in x, y, width, height (window coordinates) as the server holds
  // them: what the screen shows. Throws std::runtime_error when the server refuses.
  RgbImage read(unsigned long window, int x, int y, int width, int height);

  // The screen's root window: the desktop.
  unsigned long root() const;
  // Draws `picture` on the root window at its top-left (the rest black) and waits until the
  // server has drawn it: a desktop of known pixels.
  void show_on_root(const RgbImage& picture);

 private:
  void* display_ = nullptr;  // ::Display*; Xlib's macros stay out of the tests
};

}  // namespace l2::testing
