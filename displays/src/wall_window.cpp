#include "displays/wall_window.hpp"

#include <GLFW/glfw3.h>

#include <stdexcept>

#include "displays/colours.hpp"
#include "gl_window.hpp"
#include "glfw_session.hpp"
#include "image/turn.hpp"

namespace l2 {

namespace {

// The largest window the primary monitor has room for.
Rect usable_area() {
  GLFWmonitor* primary = glfwGetPrimaryMonitor();
  int x = 0, y = 0, w = 0, h = 0;
  if (primary) glfwGetMonitorWorkarea(primary, &x, &y, &w, &h);
  if (w <= 0 || h <= 0) return {0, 0, 1920, 1080};
  return {x, y, w, h};
}

}  // namespace

WallWindow::WallWindow(const Wall& wall, const PresenterOptions& options)
    : wall_(wall), session_(std::make_unique<GlfwSession>()) {
  const Rect area = usable_area();
  view_ = fit_wall(wall_, area.w, area.h - kDecorationAllowance, kOverlayHeight);
  WindowSpec spec;
  spec.width = view_.width;
  spec.height = view_.height;
  spec.title = options.title;
  spec.x = area.x;
  spec.y = area.y;
  spec.swap_interval = options.vsync ? 1 : 0;
  window_ = std::make_unique<GlWindow>(spec);
}

WallWindow::~WallWindow() = default;

void WallWindow::present(const FrameInfo& info, const std::vector<RgbImage>& displays) {
  if (displays.size() != wall_.displays.size()) {
    throw std::invalid_argument("present: " + std::to_string(displays.size()) +
                                " images for a wall of " + std::to_string(wall_.displays.size()) +
                                " displays");
  }
  // Re-fitted every frame: the user may have resized the window.
  const int w = window_->framebuffer_width(), h = window_->framebuffer_height();
  if (w > 0 && h > kOverlayHeight) view_ = fit_wall(wall_, w, h, kOverlayHeight);
  window_->begin_frame(kMullionColour);
  for (std::size_t i = 0; i < displays.size(); ++i) {
    const Orientation o = wall_.displays[i].orientation;
    window_->draw_image(i, o.identity() ? displays[i] : to_canvas(displays[i], o),
                        view_.display_rects[i]);
  }
  window_->draw_image(displays.size(),
                      render_overlay(overlay_line(info), view_.overlay.w, view_.overlay.h),
                      view_.overlay);
  window_->finish_drawing();
  window_->swap();  // one window: every swap group of the wall changes at once
}

UserAction WallWindow::poll_events() {
  glfwPollEvents();
  return window_->next_action();
}

std::vector<RgbImage> WallWindow::read_back() {
  std::vector<RgbImage> shown;
  for (std::size_t i = 0; i < view_.display_rects.size(); ++i) {
    shown.push_back(
        to_panel(window_->read_shown(view_.display_rects[i]), wall_.displays[i].orientation));
  }
  return shown;
}

std::vector<RgbImage> WallWindow::read_back_windows() {
  return {window_->read_shown()};
}

}  // namespace l2
