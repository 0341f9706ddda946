#include "x11_readback.hpp"

#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>

#include <bit>
#include <memory>
#include <mutex>

#include "displays/display_error.hpp"

namespace l2 {

namespace {

int g_x_error = 0;
int record_x_error(::Display*, XErrorEvent* e) {
  g_x_error = e->error_code;
  return 0;
}

// One 8-bit channel out of a pixel, wherever the visual keeps it.
std::uint8_t channel(unsigned long pixel, unsigned long mask) {
  if (mask == 0) return 0;
  const int shift = std::countr_zero(mask);
  const unsigned long max = mask >> shift;
  const unsigned long v = (pixel & mask) >> shift;
  return static_cast<std::uint8_t>(max == 255 ? v : v * 255 / max);
}

}  // namespace

RgbImage read_x11_window(GLFWwindow* glfw_window, const Rect& area) {
  ::Display* display = glfwGetX11Display();
  const Window window = glfwGetX11Window(glfw_window);
  RgbImage image(area.w, area.h);
  if (image.empty()) return image;
  static std::mutex mutex;  // the error handler is process-wide
  std::lock_guard lock(mutex);
  XSync(display, False);
  g_x_error = 0;
  auto* previous = XSetErrorHandler(record_x_error);
  XImage* raw = XGetImage(display, window, area.x, area.y, static_cast<unsigned>(area.w),
                          static_cast<unsigned>(area.h), AllPlanes, ZPixmap);
  XSync(display, False);
  XSetErrorHandler(previous);
  // XDestroyImage is a macro, hence the lambda.
  const auto destroy = [](XImage* x) { XDestroyImage(x); };
  std::unique_ptr<XImage, decltype(destroy)> ximage(raw, destroy);
  if (!ximage || g_x_error != 0) {
    throw DisplayError("cannot read the window back from the X server (is it fully on screen?)");
  }
  const unsigned long r = ximage->red_mask, g = ximage->green_mask, b = ximage->blue_mask;
  for (int y = 0; y < area.h; ++y) {
    std::uint8_t* out = image.row(y).data();
    for (int x = 0; x < area.w; ++x, out += 3) {
      const unsigned long pixel = XGetPixel(ximage.get(), x, y);
      out[0] = channel(pixel, r);
      out[1] = channel(pixel, g);
      out[2] = channel(pixel, b);
    }
  }
  return image;
}

}  // namespace l2
