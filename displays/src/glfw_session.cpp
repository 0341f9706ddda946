#include "glfw_session.hpp"

#include <GLFW/glfw3.h>

#include <cstdlib>
#include <mutex>

#include "displays/display_error.hpp"
#include "lsan_gl.hpp"

namespace l2 {

namespace {

std::mutex g_mutex;
int g_users = 0;
std::string g_last_error;

void on_glfw_error(int /*code*/, const char* description) {
  g_last_error = description ? description : "unknown GLFW error";
}

}  // namespace

std::string last_glfw_error() {
  return g_last_error;
}

GlfwSession::GlfwSession() {
  std::lock_guard lock(g_mutex);
  if (g_users == 0) {
    keep_gl_loaded();
    glfwSetErrorCallback(on_glfw_error);
    if (glfwInit() != GLFW_TRUE) {
      const char* display = std::getenv("DISPLAY");
      throw DisplayError("cannot open the screen: " + g_last_error +
                         " (DISPLAY=" + (display ? display : "unset") +
                         "; without a screen, run under Xvfb: xvfb-run -a <command>)");
    }
  }
  ++g_users;
}

GlfwSession::~GlfwSession() {
  std::lock_guard lock(g_mutex);
  if (--g_users == 0) glfwTerminate();
}

std::vector<GLFWmonitor*> GlfwSession::monitor_handles() const {
  int count = 0;
  GLFWmonitor** list = glfwGetMonitors(&count);
  return list ? std::vector<GLFWmonitor*>(list, list + count) : std::vector<GLFWmonitor*>{};
}

std::vector<MonitorInfo> GlfwSession::monitors() const {
  std::vector<MonitorInfo> infos;
  for (GLFWmonitor* m : monitor_handles()) {
    MonitorInfo info;
    const char* name = glfwGetMonitorName(m);
    info.name = name ? name : "";
    glfwGetMonitorPos(m, &info.x, &info.y);
    if (const GLFWvidmode* mode = glfwGetVideoMode(m)) {
      info.width = mode->width;
      info.height = mode->height;
    }
    infos.push_back(info);
  }
  return infos;
}

}  // namespace l2
