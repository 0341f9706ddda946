// The EGL display pipeservers render on (egl_display.cpp: finding, initialising and probing
// it once a process) and what egl_surface.cpp makes on it: a context with a pbuffer, both of the
// display's config. Internal to the pipeserver library.
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

#include "gl_surface.hpp"

namespace l2::detail {

// An initialised display and the config every context and pbuffer of it is made with: 8-bit
// RGBA and a 24-bit depth buffer, as OSMesa's.
struct EglDisplayState {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  EglTarget target;
};

// The display every EGL context of the process is made on, chosen on the first call (the GPU's
// if egl_gpu() found one, else what egl_any() finds). A copy: contexts made before a later
// decision keep the display they were made on. Throws RendererError when EGL renders nowhere.
EglDisplayState chosen_display();

// What the EGL call that just failed reports: "EGL_NOT_INITIALIZED: DRI2: failed to load driver".
std::string egl_failure();

// EGL_KHR_debug's callback (egl_errors.cpp): keeps the driver's first message of an error for
// egl_failure. forget_driver_message drops one left from a call whose failure was expected.
void on_egl_message(EGLenum error, const char* command, EGLint type, EGLLabelKHR thread,
                    EGLLabelKHR object, const char* message);
void forget_driver_message();

// A context of the display's config with a width x height pbuffer, current on return.
struct EglBinding {
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
};
// Defined in egl_surface.cpp. On failure the binding holds no context and `why` says why.
EglBinding make_binding(const EglDisplayState& d, int width, int height, std::string& why);
// Destroys the binding's context and pbuffer, unbinding them first if current.
void release_binding(EGLDisplay display, EglBinding& b);

}  // namespace l2::detail
