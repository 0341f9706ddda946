#include "displays/x_client.hpp"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>

#include <bit>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

namespace l2::testing {

namespace {

::Display* dpy(void* p) {
  return static_cast<::Display*>(p);
}

std::uint8_t channel(unsigned long pixel, unsigned long mask) {
  if (mask == 0) return 0;
  const int shift = std::countr_zero(mask);
  const unsigned long max = mask >> shift;
  return static_cast<std::uint8_t>(((pixel & mask) >> shift) * 255 / max);
}

std::string title_of(::Display* d, Window w) {
  char* name = nullptr;
  if (XFetchName(d, w, &name) == 0 || name == nullptr) return {};
  std::string title(name);
  XFree(name);
  return title;
}

// A failed request must fail the test, not end the test process (Xlib's default handler).
int g_error = 0;
int record_error(::Display*, XErrorEvent* e) {
  g_error = e->error_code;
  return 0;
}

bool viewable(::Display* d, Window w) {
  XWindowAttributes a;
  return XGetWindowAttributes(d, w, &a) != 0 && a.map_state == IsViewable;
}

}  // namespace

XClient::XClient(const std::string& display) {
  display_ = XOpenDisplay(display.c_str());
  if (!display_) throw std::runtime_error("XClient: cannot connect to X display " + display);
  int event = 0, error = 0, major = 0, minor = 0;
  if (!XTestQueryExtension(dpy(display_), &event, &error, &major, &minor)) {
    XCloseDisplay(dpy(display_));
    throw std::runtime_error("XClient: the X server " + display + " has no XTEST extension");
  }
  XSetErrorHandler(record_error);
}

XClient::~XClient() {
  XCloseDisplay(dpy(display_));
}

unsigned long XClient::wait_for_window(const std::string& title,
                                       std::chrono::milliseconds timeout) {
  ::Display* d = dpy(display_);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  do {
    Window root = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    XSync(d, False);
    if (XQueryTree(d, DefaultRootWindow(d), &root, &parent, &children, &count) != 0) {
      const std::vector<Window> windows(children, children + count);
      if (children) XFree(children);
      for (Window w : windows) {
        if (title_of(d, w) == title && viewable(d, w)) return w;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (std::chrono::steady_clock::now() < deadline);
  return 0;
}

void XClient::type(unsigned long window, const std::string& key) {
  ::Display* d = dpy(display_);
  const KeySym sym = XStringToKeysym(key.c_str());
  const KeyCode code = sym == NoSymbol ? 0 : XKeysymToKeycode(d, sym);
  if (code == 0) throw std::invalid_argument("XClient: no key for '" + key + "'");
  g_error = 0;
  XSetInputFocus(d, window, RevertToParent, CurrentTime);
  XTestFakeKeyEvent(d, code, True, CurrentTime);
  XTestFakeKeyEvent(d, code, False, CurrentTime);
  XSync(d, False);
  if (g_error != 0) throw std::runtime_error("XClient: the X server refused the key '" + key + "'");
}

RgbImage XClient::read(unsigned long window, int x, int y, int width, int height) {
  ::Display* d = dpy(display_);
  XSync(d, False);
  g_error = 0;
  const auto destroy = [](XImage* i) { XDestroyImage(i); };  // a macro, hence the lambda
  std::unique_ptr<XImage, decltype(destroy)> image(
      XGetImage(d, window, x, y, static_cast<unsigned>(width), static_cast<unsigned>(height),
                AllPlanes, ZPixmap),
      destroy);
  if (!image || g_error != 0)
    throw std::runtime_error("XClient: the X server refused to give the window back");
  RgbImage out(width, height);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const unsigned long p = XGetPixel(image.get(), col, row);
      out.set(col, row,
              {channel(p, image->red_mask), channel(p, image->green_mask),
               channel(p, image->blue_mask)});
    }
  }
  return out;
}

unsigned long XClient::root() const {
  return DefaultRootWindow(dpy(display_));
}

void XClient::show_on_root(const RgbImage& picture) {
  ::Display* d = dpy(display_);
  const int screen = DefaultScreen(d);
  const Window root = RootWindow(d, screen);
  g_error = 0;
  XSetWindowBackground(d, root, BlackPixel(d, screen));
  XClearWindow(d, root);
  const auto destroy = [](XImage* i) { XDestroyImage(i); };
  std::unique_ptr<XImage, decltype(destroy)> image(
      XGetImage(d, root, 0, 0, static_cast<unsigned>(picture.width()),
                static_cast<unsigned>(picture.height()), AllPlanes, ZPixmap),
      destroy);
  if (!image) throw std::runtime_error("XClient: cannot make an image of the root's depth");
  const auto place = [](std::uint8_t c, unsigned long mask) {
    const int shift = std::countr_zero(mask);
    return (static_cast<unsigned long>(c) * (mask >> shift) / 255) << shift;
  };
  for (int y = 0; y < picture.height(); ++y) {
    for (int x = 0; x < picture.width(); ++x) {
      const Rgb c = picture.at(x, y);
      XPutPixel(image.get(), x, y,
                place(c.r, image->red_mask) | place(c.g, image->green_mask) |
                    place(c.b, image->blue_mask));
    }
  }
  // Drawn on the root itself: nothing covers or clears it while the test runs.
  const GC gc = XCreateGC(d, root, 0, nullptr);
  XPutImage(d, root, gc, image.get(), 0, 0, 0, 0, static_cast<unsigned>(picture.width()),
            static_cast<unsigned>(picture.height()));
  XFreeGC(d, gc);
  XSync(d, False);
  if (g_error != 0) throw std::runtime_error("XClient: the X server refused the root's picture");
}

}  // namespace l2::testing
