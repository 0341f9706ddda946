#include "displays/monitor_wall.hpp"

#include <GLFW/glfw3.h>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "displays/colours.hpp"
#include "displays/monitor_map.hpp"
#include "displays/swap_groups.hpp"
#include "displays/wall_view.hpp"
#include "gl_window.hpp"
#include "glfw_session.hpp"
#include "image/turn.hpp"

namespace l2 {

MonitorWall::MonitorWall(const Wall& wall, const PresenterOptions& options)
    : wall_(wall), session_(std::make_unique<GlfwSession>()), groups_(swap_groups(wall)) {
  const std::vector<int> chosen = map_displays_to_monitors(wall_, session_->monitors());
  const std::vector<GLFWmonitor*> handles = session_->monitor_handles();
  const std::vector<MonitorInfo> monitors = session_->monitors();
  windows_.resize(wall_.displays.size());
  for (const std::vector<int>& group : groups_) {
    for (std::size_t k = 0; k < group.size(); ++k) {
      const int d = group[k];
      GLFWmonitor* monitor = handles[chosen[d]];
      const GLFWvidmode* mode = glfwGetVideoMode(monitor);
      WindowSpec spec;
      // The monitor's current mode: fullscreen without a mode switch, and the display's pixels
      // at their own size in the middle of it.
      spec.width = mode ? mode->width : wall_.displays[d].width;
      spec.height = mode ? mode->height : wall_.displays[d].height;
      spec.title = options.title + " - display " + std::to_string(wall_.displays[d].id);
      spec.fullscreen_on = monitor;
      note_scaled(wall_.displays[d], spec.width, spec.height, monitors[chosen[d]].name);
      // One vertical-blank wait per group: the other windows of the group swap right after it.
      spec.swap_interval = options.vsync && k == 0 ? 1 : 0;
      windows_[d] = std::make_unique<GlWindow>(spec);
    }
  }
  shown_.resize(wall_.displays.size());
}

MonitorWall::~MonitorWall() = default;

void MonitorWall::note_scaled(const Display& d, int width, int height, const std::string& monitor) {
  const Rect r = d.on_canvas();
  if (r.w <= width && r.h <= height) return;
  const double scale = std::min(double(width) / r.w, double(height) / r.h);
  notes_.push_back(fmt::format(
      "display {} ({}x{} as it hangs) is shown at {:.0f}% on monitor {} ({}x{}): the monitor is "
      "smaller than the panel",
      d.id, r.w, r.h, 100.0 * scale, monitor, width, height));
}

void MonitorWall::present(const FrameInfo& /*info*/, const std::vector<RgbImage>& displays) {
  if (displays.size() != wall_.displays.size()) {
    throw std::invalid_argument("present: " + std::to_string(displays.size()) +
                                " images for a wall of " + std::to_string(wall_.displays.size()) +
                                " displays");
  }
  // Draw every window first, then swap each group back to back from this one thread.
  for (std::size_t d = 0; d < displays.size(); ++d) {
    GlWindow& w = *windows_[d];
    w.begin_frame({0, 0, 0});
    // As the panel hangs: a portrait panel stands upright on a landscape monitor.
    const Orientation o = wall_.displays[d].orientation;
    const RgbImage& hanging = o.identity() ? displays[d] : (turned_ = to_canvas(displays[d], o));
    shown_[d] = fit_display(hanging.width(), hanging.height(), w.framebuffer_width(),
                            w.framebuffer_height());
    w.draw_image(0, hanging, shown_[d]);
    w.finish_drawing();
  }
  for (const std::vector<int>& group : groups_) {
    for (int d : group) windows_[d]->swap();
  }
}

UserAction MonitorWall::poll_events() {
  glfwPollEvents();
  for (auto& w : windows_) {
    if (const UserAction a = w->next_action(); a != UserAction::None) return a;
  }
  return UserAction::None;
}

std::vector<RgbImage> MonitorWall::read_back() {
  std::vector<RgbImage> shown;
  for (std::size_t d = 0; d < windows_.size(); ++d)
    shown.push_back(to_panel(windows_[d]->read_shown(shown_[d]), wall_.displays[d].orientation));
  return shown;
}

std::vector<RgbImage> MonitorWall::read_back_windows() {
  std::vector<RgbImage> shown;
  for (auto& w : windows_) shown.push_back(w->read_shown());
  return shown;
}

}  // namespace l2
