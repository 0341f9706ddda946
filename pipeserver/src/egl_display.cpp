// Finding the EGL display pipeservers render on, without a window system: a display on an EGL
// device (EGL_EXT_platform_device: a GPU's, else Mesa's software device) or on Mesa's
// surfaceless platform, initialised with OSMesa's config and probed with a context once a
// process. EGL's errors with the driver's own reason: egl_errors.cpp; the contexts and pbuffers
// made on the display: egl_surface.cpp.
#include "egl_display.hpp"

#include <EGL/eglext.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "pipeserver/gl_context.hpp"

namespace l2::detail {
namespace {

// EGL's client side, once a process: the extensions without a display, and the functions of
// those a pipeserver uses.
struct EglClient {
  bool any_vendor = false;  // glvnd found an EGL driver (the client extensions are listed)
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC device_string = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC platform_display = nullptr;
  bool surfaceless = false;  // EGL_MESA_platform_surfaceless
};

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(std::string(" ") + name + " ") != std::string::npos;
}

const EglClient& egl_client() {
  static EglClient c;
  static std::once_flag once;
  std::call_once(once, [] {
    // Mesa's loader warnings (a driver it cannot open) would otherwise go to stderr on their own
    // lines from every pipeserver; what failed, with the driver's reason, is in the one line a
    // failure gives. EGL_LOG_LEVEL set by the user is kept.
    ::setenv("EGL_LOG_LEVEL", "fatal", 0);
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    c.any_vendor = client != nullptr && client[0] != '\0';
    if (has_extension(client, "EGL_KHR_debug")) {
      const auto control = reinterpret_cast<PFNEGLDEBUGMESSAGECONTROLKHRPROC>(
          eglGetProcAddress("eglDebugMessageControlKHR"));
      const EGLAttrib errors[] = {EGL_DEBUG_MSG_CRITICAL_KHR, EGL_TRUE, EGL_DEBUG_MSG_ERROR_KHR,
                                  EGL_TRUE, EGL_NONE};
      if (control != nullptr) control(on_egl_message, errors);
    }
    if (has_extension(client, "EGL_EXT_device_enumeration")) {
      c.query_devices =
          reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    }
    if (has_extension(client, "EGL_EXT_device_query")) {
      c.device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
          eglGetProcAddress("eglQueryDeviceStringEXT"));
    }
    if (has_extension(client, "EGL_EXT_platform_base")) {
      c.platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
          eglGetProcAddress("eglGetPlatformDisplayEXT"));
    }
    c.surfaceless = has_extension(client, "EGL_MESA_platform_surfaceless");
    forget_driver_message();
  });
  return c;
}

struct EglDevice {
  EGLDeviceEXT handle = EGL_NO_DEVICE_EXT;
  std::string name;  // "GPU /dev/dri/renderD128", "Mesa's software device"
  bool software = false;
};

std::vector<EglDevice> egl_devices(const EglClient& c) {
  std::vector<EglDevice> out;
  if (c.query_devices == nullptr || c.device_string == nullptr) return out;
  EGLint count = 0;
  if (!c.query_devices(0, nullptr, &count) || count <= 0) {
    forget_driver_message();
    return out;
  }
  std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(count));
  if (!c.query_devices(count, handles.data(), &count)) return out;
  handles.resize(static_cast<std::size_t>(std::max(count, 0)));
  for (std::size_t i = 0; i < handles.size(); ++i) {
    EglDevice d{handles[i], {}, false};
    const char* extensions = c.device_string(d.handle, EGL_EXTENSIONS);
    d.software = has_extension(extensions, "EGL_MESA_device_software");
    const char* node = has_extension(extensions, "EGL_EXT_device_drm_render_node")
                           ? c.device_string(d.handle, EGL_DRM_RENDER_NODE_FILE_EXT)
                           : nullptr;
    if (node == nullptr && has_extension(extensions, "EGL_EXT_device_drm"))
      node = c.device_string(d.handle, EGL_DRM_DEVICE_FILE_EXT);
    if (d.software)
      d.name = "Mesa's software device";
    else if (node != nullptr)
      d.name = fmt::format("GPU {}", node);
    else
      d.name = fmt::format("EGL device {}", i);
    forget_driver_message();
    out.push_back(std::move(d));
  }
  return out;
}

// A software rasteriser by the name it gives GL_RENDERER: what a device without a GPU behind
// it (a virtual one, kms_swrast) renders with.
bool software_renderer(const std::string& gl_renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer", "SwiftShader"})
    if (gl_renderer.find(name) != std::string::npos) return true;
  return false;
}

std::optional<EGLConfig> choose_config(EGLDisplay display, std::string& why) {
  const EGLint wanted[] = {EGL_SURFACE_TYPE,
                           EGL_PBUFFER_BIT,
                           EGL_RENDERABLE_TYPE,
                           EGL_OPENGL_BIT,
                           EGL_RED_SIZE,
                           8,
                           EGL_GREEN_SIZE,
                           8,
                           EGL_BLUE_SIZE,
                           8,
                           EGL_ALPHA_SIZE,
                           8,
                           EGL_DEPTH_SIZE,
                           24,
                           EGL_NONE};
  EGLint count = 0;
  if (!eglChooseConfig(display, wanted, nullptr, 0, &count) || count <= 0) {
    why = "no config with 8-bit RGBA, a 24-bit depth buffer and pbuffers for OpenGL";
    forget_driver_message();
    return std::nullopt;
  }
  std::vector<EGLConfig> configs(static_cast<std::size_t>(count));
  eglChooseConfig(display, wanted, configs.data(), count, &count);
  const auto attribute = [display](EGLConfig c, EGLint name) {
    EGLint v = 0;
    eglGetConfigAttrib(display, c, name, &v);
    return v;
  };
  // Exactly 8 bits a channel (a larger size sorts first) and exactly 24 of depth if there is one.
  std::optional<EGLConfig> best;
  for (EGLConfig c : configs) {
    if (attribute(c, EGL_RED_SIZE) != 8 || attribute(c, EGL_GREEN_SIZE) != 8 ||
        attribute(c, EGL_BLUE_SIZE) != 8 || attribute(c, EGL_ALPHA_SIZE) != 8)
      continue;
    if (attribute(c, EGL_DEPTH_SIZE) == 24) return c;
    if (!best) best = c;
  }
  if (!best) why = "no config with exactly 8 bits a colour channel";
  return best;
}

// Opens `display` (named `name`) as a display pipeservers can render on: initialised, a config,
// and a context that names its GL. nullopt with `why` when not.
std::optional<EglDisplayState> open_display(EGLDisplay display, const std::string& name,
                                            std::string& why) {
  if (display == EGL_NO_DISPLAY) {
    why = fmt::format("{}: no display ({})", name, egl_failure());
    return std::nullopt;
  }
  if (!eglInitialize(display, nullptr, nullptr)) {
    why = fmt::format("{}: eglInitialize failed ({})", name, egl_failure());
    return std::nullopt;
  }
  EglDisplayState d{display, nullptr, {}};
  std::string no_config;
  const std::optional<EGLConfig> config = choose_config(display, no_config);
  if (!config) {
    why = fmt::format("{}: {}", name, no_config);
    return std::nullopt;
  }
  d.config = *config;
  std::string failed;
  EglBinding probe = make_binding(d, 1, 1, failed);
  if (probe.context == EGL_NO_CONTEXT) {
    why = fmt::format("{}: {}", name, failed);
    return std::nullopt;
  }
  const auto get_string = reinterpret_cast<const GLubyte* (*)(GLenum)>(
      reinterpret_cast<void*>(eglGetProcAddress("glGetString")));
  const auto text = [get_string](GLenum what) {
    const auto* s = get_string ? reinterpret_cast<const char*>(get_string(what)) : nullptr;
    return std::string(s ? s : "");
  };
  d.target = {name, false, text(GL_RENDERER), text(GL_VERSION)};
  release_binding(display, probe);
  if (d.target.gl_renderer.empty()) {
    why = fmt::format("{}: its context names no GL_RENDERER", name);
    return std::nullopt;
  }
  d.target.gpu = !software_renderer(d.target.gl_renderer);
  return d;
}

// What the process found, probed once each.
struct EglProbes {
  std::mutex mutex;
  bool gpu_probed = false;
  std::optional<EglDisplayState> gpu;
  std::string no_gpu;  // why not
  bool any_probed = false;
  std::optional<EglDisplayState> any;
  std::string no_any;                     // why not
  std::optional<EglDisplayState> chosen;  // the display of every EGL context
};
EglProbes& probes() {
  static EglProbes p;
  return p;
}

// Called with the mutex held.
void probe_gpu(EglProbes& p) {
  if (p.gpu_probed) return;
  p.gpu_probed = true;
  const EglClient& c = egl_client();
  if (!c.any_vendor) {
    p.no_gpu =
        "no GPU: EGL finds no driver (glvnd lists no EGL vendor: Debian's libegl-mesa0, or "
        "the GPU's own)";
    return;
  }
  if (c.query_devices == nullptr || c.platform_display == nullptr) {
    p.no_gpu = "no GPU: EGL cannot list devices (no EGL_EXT_device_enumeration or platform_base)";
    return;
  }
  const std::vector<EglDevice> devices = egl_devices(c);
  std::vector<std::string> notes;
  for (const EglDevice& d : devices) {
    if (d.software) continue;
    std::string why;
    auto display =
        open_display(c.platform_display(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr), d.name, why);
    if (!display) {
      notes.push_back(why);
    } else if (!display->target.gpu) {
      notes.push_back(fmt::format("{} renders with {}", d.name, display->target.gl_renderer));
    } else {
      p.gpu = std::move(display);
      return;
    }
  }
  if (!notes.empty()) {
    p.no_gpu = "no GPU: ";
    for (std::size_t i = 0; i < notes.size(); ++i) p.no_gpu += (i ? "; " : "") + notes[i];
  } else if (devices.empty()) {
    p.no_gpu = "no GPU: EGL finds no device";
  } else {
    p.no_gpu = "no GPU: EGL finds only Mesa's software device (llvmpipe)";
  }
}

// Called with the mutex held.
void probe_any(EglProbes& p) {
  if (p.any_probed) return;
  p.any_probed = true;
  probe_gpu(p);
  if (p.gpu) {
    p.any = p.gpu;
    return;
  }
  const EglClient& c = egl_client();
  if (!c.any_vendor) {
    p.no_any = "EGL finds no driver (glvnd lists no EGL vendor: Debian's libegl-mesa0)";
    return;
  }
  std::vector<std::string> notes;
  if (c.platform_display != nullptr) {
    for (const EglDevice& d : egl_devices(c)) {
      if (!d.software) continue;
      std::string why;
      p.any =
          open_display(c.platform_display(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr), d.name, why);
      if (p.any) return;
      notes.push_back(why);
    }
    if (c.surfaceless) {
      std::string why;
      p.any = open_display(
          c.platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
          "Mesa's surfaceless platform", why);
      if (p.any) return;
      notes.push_back(why);
    }
  }
  if (notes.empty()) {
    p.no_any = "EGL offers neither devices (EGL_EXT_platform_device) nor the surfaceless platform";
    return;
  }
  for (std::size_t i = 0; i < notes.size(); ++i) p.no_any += (i ? "; " : "") + notes[i];
}

}  // namespace

EglDisplayState chosen_display() {
  EglProbes& p = probes();
  std::lock_guard lock(p.mutex);
  if (!p.chosen) {
    probe_any(p);
    if (!p.any) throw RendererError("--renderer egl: no EGL display can render here: " + p.no_any);
    p.chosen = p.any;
  }
  return *p.chosen;
}

std::optional<EglTarget> egl_gpu(std::string& why_not) {
  EglProbes& p = probes();
  std::lock_guard lock(p.mutex);
  probe_gpu(p);
  if (!p.gpu) {
    why_not = p.no_gpu;
    return std::nullopt;
  }
  p.chosen = p.gpu;
  return p.gpu->target;
}

EglTarget egl_any() {
  {
    EglProbes& p = probes();
    std::lock_guard lock(p.mutex);
    probe_any(p);
    if (!p.any) throw RendererError("--renderer egl: no EGL display can render here: " + p.no_any);
    p.chosen = p.any;
  }
  return chosen_display().target;
}

}  // namespace l2::detail
