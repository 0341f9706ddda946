// The off-screen OpenGL contexts pipeservers render with, and the renderer behind them
// (--renderer, renderer_choice.hpp): OSMesa, Mesa's off-screen software rasteriser, or EGL
// without a window system, on the machine's GPU or on Mesa's software device (llvmpipe). Either
// way a context renders into a surface of its own with an 8-bit RGBA colour buffer and a 24-bit
// depth buffer, and finish() brings the pixels into one caller-visible RGBA buffer, rows bottom
// to top: everything downstream is one code path. The scenes draw through the current context's
// function table (gl_api.hpp), never through plain gl* symbols.
//
// A pipeserver owns one context per display size; the reference render owns its own so it never
// disturbs a pipeserver's framebuffer. A thread has one context current at a time, of either
// renderer.
//
// Example:
//   const RendererDecision d = use_renderer(RendererChoice::Auto);  // EGL on a GPU, else OSMesa
//   std::printf("renderer: %s\n", d.line().c_str());
//   GlContext context(640, 480);  // the decided renderer, current on this thread
//   gl().Clear(GL_COLOR_BUFFER_BIT);
//   context.finish();
//   const std::uint8_t* pixels = context.rgba();
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeserver/gl_api.hpp"
#include "pipeserver/renderer_choice.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

namespace detail {
class GlSurface;  // a renderer's context and surface (src/gl_surface.hpp)
}

enum class Renderer { OsMesa, Egl };
const char* renderer_name(Renderer renderer);  // "osmesa", "egl"

// A renderer that cannot render here (EGL asked for where no EGL display can be made, or
// libOSMesa missing): its message is one line, starting with what was asked for.
class RendererError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a --renderer choice decided on this machine, and why: what a pipeserver says it renders
// with (its log, the run's summary, `pipeserver --gl-info`).
struct RendererDecision {
  Renderer renderer = Renderer::OsMesa;
  std::string gl_renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string gl_version;   // GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6"
  // EGL's device: "GPU /dev/dri/renderD128", "Mesa's software device" ...; empty for OSMesa.
  std::string device;
  // How it was decided: "--renderer egl", "auto: EGL finds a GPU", "auto: no GPU: EGL finds
  // only Mesa's software device (llvmpipe)", ...
  std::string why;
  // One line, e.g. "egl (llvmpipe (LLVM 15.0.6, 256 bits), EGL device: Mesa's software device;
  // --renderer egl)": the renderer, its GL_RENDERER, EGL's device, why.
  std::string line() const;
};

// Decides what `choice` renders with here — auto: EGL when EGL finds a GPU (a device that is not
// Mesa's software device and does not render with a software rasteriser), else OSMesa, saying
// why — makes it the process's renderer and returns the decision. Throws RendererError when the
// renderer asked for cannot render here (one line: what failed, and EGL's own reason). Leaves no
// GL context current on the calling thread (it makes contexts of its own to ask them).
RendererDecision use_renderer(RendererChoice choice);
// What GlContexts made without a renderer render with: OSMesa until use_renderer() decides.
Renderer process_renderer();

class GlContext {
 public:
  // Throws RendererError when the renderer cannot make the context, std::runtime_error for a bad
  // size. The new context is current on the calling thread.
  GlContext(int width, int height);  // process_renderer()'s
  GlContext(int width, int height, Renderer renderer);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds this context to the calling thread (and unbinds the one that was, of either
  // renderer). Cheap when already current.
  void make_current();
  // Waits for what was drawn and brings it into rgba(): OSMesa draws into that buffer (glFinish
  // copies it there); EGL's surface is read back into it with glReadPixels. Must be current.
  void finish();
  // The same for the pixels of `regions` only (GL window coordinates: x from the left, y from
  // the bottom row), each read into its place in rgba(); the rest of rgba() is left as it was.
  // A pipeserver reads back its tiles, not the whole display-sized window.
  void finish(std::span<const Rect> regions);

  Renderer renderer() const { return renderer_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // RGBA, 4 bytes a pixel, rows bottom to top (OpenGL's origin). Valid after finish().
  const std::uint8_t* rgba() const { return buffer_.data(); }

 private:
  Renderer renderer_;
  int width_, height_;
  std::vector<std::uint8_t> buffer_;
  std::unique_ptr<detail::GlSurface> surface_;
};

// The OpenGL implementation a renderer renders with, as it names itself. Rendered pixels
// depend on it (rasterisation rounding changes between Mesa and LLVM versions, and with the
// CPU's vector width), so golden images of rendered scenes record it. On llvmpipe OSMesa and
// EGL name themselves alike, and render alike.
struct GlInfo {
  std::string version;   // GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6"
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  // The Mesa release named in `version` ("22.3.6"); empty when it names none.
  std::string mesa_version() const;
};

// Asks a 1x1 context of its own. Throws as GlContext does.
GlInfo gl_info();  // process_renderer()'s
GlInfo gl_info(Renderer renderer);

}  // namespace l2
