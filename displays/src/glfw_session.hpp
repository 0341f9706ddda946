// GLFW for the lifetime of the presenters: initialised by the first, terminated after the last,
// with GLFW's own error text kept so a failure reads as one clear line.
#pragma once

#include <string>
#include <vector>

#include "displays/monitor_map.hpp"

struct GLFWmonitor;

namespace l2 {

class GlfwSession {
 public:
  GlfwSession();  // throws DisplayError when there is no X display to open
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;

  // The monitors GLFW sees, primary first, with their handles in the same order.
  std::vector<MonitorInfo> monitors() const;
  std::vector<GLFWmonitor*> monitor_handles() const;
};

// The last error GLFW reported ("" if none), for messages.
std::string last_glfw_error();

}  // namespace l2
