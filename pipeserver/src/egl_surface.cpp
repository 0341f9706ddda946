// EGL behind GlContext: one OpenGL (compatibility profile) context per GlContext on the
// process's EGL display (egl_display.hpp), drawing into a pbuffer of the context's size that
// finish() reads back with glReadPixels.
//
// A pbuffer, not a framebuffer object: Mesa stores a window-system surface (a pbuffer, and
// OSMesa's own buffer) top row first and draws it with the viewport turned upside down, while a
// framebuffer object is stored bottom row first. llvmpipe rasterises in the order it stores, so
// the same triangle drawn into a framebuffer object comes out mirrored at the pixel level:
// other pixels on edges that pass through pixel centres, and colours and depths interpolated
// from another corner, rounded differently (measured: 41 of 83,583 colour pixels and 40,377
// depth values differ from OSMesa's on a test scene; none in a pbuffer, nor in a framebuffer
// object drawn upside down). In a pbuffer EGL on llvmpipe gives OSMesa's pixels exactly.
#include <fmt/format.h>

#include <cstring>
#include <stdexcept>

#include "egl_display.hpp"
#include "gl_surface.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2::detail {

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

void release_binding(EGLDisplay display, EglBinding& b) {
  if (eglGetCurrentContext() == b.context)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (b.context != EGL_NO_CONTEXT) eglDestroyContext(display, b.context);
  if (b.surface != EGL_NO_SURFACE) eglDestroySurface(display, b.surface);
  b = {};
}

namespace {

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
  ~EglSurface() override { release_binding(display_.display, binding_); }
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

std::unique_ptr<GlSurface> egl_surface(int width, int height) {
  return std::make_unique<EglSurface>(width, height);
}

}  // namespace l2::detail
