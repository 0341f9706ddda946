// EGL behind GlContext, without a window system: a display on an EGL device
// (EGL_EXT_platform_device: a GPU's, else Mesa's software device) or on Mesa's surfaceless
// platform, one OpenGL (compatibility profile) context per GlContext, drawing into a pbuffer
// of the context's size that finish() reads back with glReadPixels.
//
// A pbuffer, not a framebuffer object: Mesa stores a window-system surface (a pbuffer, and
// OSMesa's own buffer) top row first and draws it with the viewport turned upside down, while a
// framebuffer object is stored bottom row first. llvmpipe rasterises in the order it stores, so
// the same triangle drawn into a framebuffer object comes out mirrored at the pixel level:
// other pixels on edges that pass through pixel centres, and colours and depths interpolated
// from another corner, rounded differently (measured: 41 of 83,583 colour pixels and 40,377
// depth values differ from OSMesa's on a test scene; none in a pbuffer, nor in a framebuffer
// object drawn upside down). In a pbuffer EGL on llvmpipe gives OSMesa's pixels exactly.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "gl_surface.hpp"
#include "pipeserver/gl_context.hpp"

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

// The first message the driver gave with its latest error (EGL_KHR_debug), which says more than
// the error code ("DRI2: failed to load driver"). Set from EGL's calls on this process's threads;
// read right after the call that failed.
std::mutex g_message_mutex;
std::string g_driver_message;

void on_egl_message(EGLenum, const char* command, EGLint, EGLLabelKHR, EGLLabelKHR,
                    const char* message) {
  std::lock_guard lock(g_message_mutex);
  // EGL's last words name the command only ("eglInitialize"): the driver's reason comes first.
  if (!g_driver_message.empty() || message == nullptr) return;
  if (command != nullptr && std::string(message) == command) return;
  g_driver_message = message;
}

// What the call that just failed reports: "EGL_NOT_INITIALIZED: DRI2: failed to load driver".
std::string egl_failure() {
  const EGLint e = eglGetError();
  std::lock_guard lock(g_message_mutex);
  std::string text = egl_error_name(e);
  if (!g_driver_message.empty()) text += ": " + g_driver_message;
  g_driver_message.clear();
  return text;
}

void forget_driver_message() {
  std::lock_guard lock(g_message_mutex);
  g_driver_message.clear();
}

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

// An initialised display and the config every context and pbuffer of it is made with: 8-bit
// RGBA and a 24-bit depth buffer, as OSMesa's.
struct EglDisplayState {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  EglTarget target;
};

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

// A context of the display's config with a width x height pbuffer, current on return.
struct EglBinding {
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
};
EglBinding make_binding(const EglDisplayState& d, int width, int height, std::string& why) {
  EglBinding b;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "no desktop OpenGL (eglBindAPI: " + egl_failure() + ")";
    return b;
  }
  const EGLint size[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  b.surface = eglCreatePbufferSurface(d.display, d.config, size);
  if (b.surface == EGL_NO_SURFACE) {
    why = fmt::format("eglCreatePbufferSurface {}x{}: {}", width, height, egl_failure());
    return b;
  }
  // No version asked: the compatibility profile, whose fixed-function pipeline the scenes use.
  const EGLint none[] = {EGL_NONE};
  b.context = eglCreateContext(d.display, d.config, EGL_NO_CONTEXT, none);
  if (b.context == EGL_NO_CONTEXT) {
    why = "eglCreateContext: " + egl_failure();
    eglDestroySurface(d.display, b.surface);
    b.surface = EGL_NO_SURFACE;
    return b;
  }
  if (!eglMakeCurrent(d.display, b.surface, b.surface, b.context)) {
    why = "eglMakeCurrent: " + egl_failure();
    eglDestroyContext(d.display, b.context);
    eglDestroySurface(d.display, b.surface);
    b = {};
  }
  return b;
}

void release(EGLDisplay display, EglBinding& b) {
  if (eglGetCurrentContext() == b.context)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (b.context != EGL_NO_CONTEXT) eglDestroyContext(display, b.context);
  if (b.surface != EGL_NO_SURFACE) eglDestroySurface(display, b.surface);
  b = {};
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
  release(display, probe);
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

// A copy: contexts made before a later decision keep the display they were made on.
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

// B and R swapped in `n` pixels, in place.
void bgra_to_rgba(std::uint8_t* p, int n) {
  for (int i = 0; i < n; ++i, p += 4) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    v = (v & 0xFF00FF00u) | ((v >> 16) & 0xFFu) | ((v & 0xFFu) << 16);
    std::memcpy(p, &v, 4);
  }
}

class EglSurface final : public GlSurface {
 public:
  EglSurface(int width, int height) : display_(chosen_display()) {
    std::string why;
    binding_ = make_binding(display_, width, height, why);
    if (binding_.context == EGL_NO_CONTEXT)
      throw RendererError(fmt::format("egl ({}): {}", display_.target.device, why));
    load_api("egl");
  }
  ~EglSurface() override { release(display_.display, binding_); }
  EglSurface(const EglSurface&) = delete;
  EglSurface& operator=(const EglSurface&) = delete;

  void bind() override {
    eglBindAPI(EGL_OPENGL_API);  // the thread's API, which eglGetCurrentContext answers for
    if (!eglMakeCurrent(display_.display, binding_.surface, binding_.surface, binding_.context))
      throw std::runtime_error("egl: eglMakeCurrent failed: " + egl_failure());
  }
  void unbind() override {
    if (bound()) eglMakeCurrent(display_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  bool bound() const override { return eglGetCurrentContext() == binding_.context; }
  // Each region into its place in a buffer of `width` pixels a row, read as BGRA and turned
  // into RGBA here: BGRA is how llvmpipe keeps its surfaces (and the fast path of desktop GPUs),
  // and Mesa's own conversion to RGBA is the slow part of a read. A 640x480 window here: 0.32 ms
  // read as RGBA, 0.06 ms as BGRA, 0.12 ms with the turn. A pipeserver reads its tiles only.
  void finish(std::uint8_t* rgba, int width, int, std::span<const Rect> regions) override {
    api_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    api_.PixelStorei(GL_PACK_ROW_LENGTH, width);
    const auto row_of = [rgba, width](int x, int y) {
      return rgba + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x)) *
                        4;
    };
    for (const Rect& r : regions) {
      if (r.empty()) continue;
      api_.ReadPixels(r.x, r.y, r.w, r.h, GL_BGRA, GL_UNSIGNED_BYTE, row_of(r.x, r.y));
      for (int y = r.y; y < r.bottom(); ++y) bgra_to_rgba(row_of(r.x, y), r.w);
    }
    api_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  }
  void* proc(const char* name) const override {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
  }

 private:
  const EglDisplayState display_;
  EglBinding binding_;
};

}  // namespace

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

std::unique_ptr<GlSurface> egl_surface(int width, int height) {
  return std::make_unique<EglSurface>(width, height);
}

}  // namespace l2::detail
