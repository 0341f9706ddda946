// The renderers behind GlContext (gl_context.hpp): each makes a context with a surface of its
// own, binds it to a thread, loads the GL function table from its own library and brings what
// was drawn into the context's RGBA buffer. OSMesa: osmesa_surface.cpp, libOSMesa loaded by name
// so that its gl* symbols stay its own. EGL: egl_surface.cpp on the display egl_display.cpp
// finds, through glvnd's libEGL.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "pipeserver/gl_api.hpp"
#include "tilelayout/geometry.hpp"

namespace l2::detail {

class GlSurface {
 public:
  virtual ~GlSurface() = default;
  // Binds the context and its surface to the calling thread. Throws std::runtime_error.
  virtual void bind() = 0;
  // Unbinds this renderer's current context from the calling thread.
  virtual void unbind() = 0;
  // Whether the renderer itself says this context is the calling thread's current one.
  virtual bool bound() const = 0;
  // Waits for the drawing and brings the pixels of `regions` (GL window coordinates) of the
  // width x height surface into their places in `rgba` (rows bottom to top).
  virtual void finish(std::uint8_t* rgba, int width, int height, std::span<const Rect> regions) = 0;
  // A GL function of this renderer by name; nullptr when it has none.
  virtual void* proc(const char* name) const = 0;
  const GlApi& api() const { return api_; }

 protected:
  // Fills api_ through proc(). Throws std::runtime_error naming a function the renderer lacks.
  void load_api(const char* renderer);
  GlApi api_;
};

// A context drawing into `rgba` (width x height, RGBA, rows bottom to top), OSMesa's own buffer.
// Throws RendererError when libOSMesa cannot be loaded or the context not made.
std::unique_ptr<GlSurface> osmesa_surface(std::uint8_t* rgba, int width, int height);

// A context drawing into a width x height pbuffer of EGL's display (chosen_display(),
// egl_display.hpp), read back with glReadPixels. Throws RendererError.
std::unique_ptr<GlSurface> egl_surface(int width, int height);

// Where EGL renders in this process: the display every EGL context is made on.
struct EglTarget {
  std::string device;  // "GPU /dev/dri/renderD128", "Mesa's software device", ...
  bool gpu = false;    // a device that is no software rasteriser
  std::string gl_renderer, gl_version;
};
// The GPU EGL renders on, made the process's EGL display; or nullopt, with `why_not` saying why
// there is none ("no GPU: EGL finds only Mesa's software device (llvmpipe)", "no EGL: ...").
std::optional<EglTarget> egl_gpu(std::string& why_not);
// What `--renderer egl` renders on: the GPU's device if EGL finds one, else Mesa's software
// device, else Mesa's surfaceless platform; made the process's EGL display. Throws RendererError
// ("--renderer egl: no EGL display: ..."), with EGL's own reason.
EglTarget egl_any();

}  // namespace l2::detail
