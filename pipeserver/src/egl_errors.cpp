// EGL's errors for people: the error's name and the first message the driver gave with it
// (EGL_KHR_debug), which says more than the code ("DRI2: failed to load driver").

#include <mutex>
#include <string>

#include "egl_display.hpp"

namespace l2::detail {
namespace {

const char* egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default:
      return "EGL error";
  }
}

// The first message the driver gave with its latest error. Set from EGL's calls on this
// process's threads; read right after the call that failed.
std::mutex g_message_mutex;
std::string g_driver_message;

}  // namespace

void on_egl_message(EGLenum, const char* command, EGLint, EGLLabelKHR, EGLLabelKHR,
                    const char* message) {
  std::lock_guard lock(g_message_mutex);
  // EGL's last words name the command only ("eglInitialize"): the driver's reason comes first.
  if (!g_driver_message.empty() || message == nullptr) return;
  if (command != nullptr && std::string(message) == command) return;
  g_driver_message = message;
}

void forget_driver_message() {
  std::lock_guard lock(g_message_mutex);
  g_driver_message.clear();
}

std::string egl_failure() {
  const EGLint e = eglGetError();
  std::lock_guard lock(g_message_mutex);
  std::string text = egl_error_name(e);
  if (!g_driver_message.empty()) text += ": " + g_driver_message;
  g_driver_message.clear();
  return text;
}

}  // namespace l2::detail
