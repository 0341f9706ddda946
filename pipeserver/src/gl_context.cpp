#include "pipeserver/gl_context.hpp"

#include <fmt/format.h>

#include <atomic>
#include <stdexcept>
#include <type_traits>

#include "gl_surface.hpp"

namespace l2 {

namespace {

// The context current on this thread, as this file made it so: the renderers keep their own
// records (OSMesa's and glvnd's), which know nothing of each other's contexts.
thread_local GlContext* t_current = nullptr;
thread_local detail::GlSurface* t_surface = nullptr;

std::atomic<Renderer> g_process_renderer{Renderer::OsMesa};

}  // namespace

namespace detail {

void GlSurface::load_api(const char* renderer) {
  const auto load = [&](auto& member, const char* name) {
    void* p = proc(name);
    if (p == nullptr)
      throw RendererError(fmt::format("{}: the renderer has no {}", renderer, name));
    member = reinterpret_cast<std::remove_reference_t<decltype(member)>>(p);
  };
#define L2_GL_LOAD(name) load(api_.name, "gl" #name);
  L2_GL_FUNCTIONS_1_1(L2_GL_LOAD)
#undef L2_GL_LOAD
#define L2_GL_LOAD(name, type) load(api_.name, "gl" #name);
  L2_GL_FUNCTIONS_LATER(L2_GL_LOAD)
#undef L2_GL_LOAD
}

}  // namespace detail

const GlApi& gl() {
  if (t_surface == nullptr) throw std::logic_error("gl(): no GL context is current on this thread");
  return t_surface->api();
}

void* gl_proc(const char* name) {
  if (t_surface == nullptr)
    throw std::logic_error("gl_proc(): no GL context is current on this thread");
  return t_surface->proc(name);
}

const char* renderer_name(Renderer renderer) {
  return renderer == Renderer::Egl ? "egl" : "osmesa";
}

Renderer process_renderer() {
  return g_process_renderer.load();
}

std::string RendererDecision::line() const {
  std::string where = gl_renderer;
  if (!device.empty()) where += ", EGL device: " + device;
  return fmt::format("{} ({}; {})", renderer_name(renderer), where, why);
}

RendererDecision use_renderer(RendererChoice choice) {
  // The probes bind contexts of their own: no context of this thread's stays current.
  if (t_current != nullptr) {
    t_surface->unbind();
    t_current = nullptr;
    t_surface = nullptr;
  }
  RendererDecision d;
  switch (choice) {
    case RendererChoice::OsMesa:
      d.renderer = Renderer::OsMesa;
      d.why = "--renderer osmesa";
      break;
    case RendererChoice::Egl: {
      const detail::EglTarget t = detail::egl_any();
      d.renderer = Renderer::Egl;
      d.device = t.device;
      d.why = "--renderer egl";
      break;
    }
    case RendererChoice::Auto: {
      std::string why_not;
      if (const auto gpu = detail::egl_gpu(why_not)) {
        d.renderer = Renderer::Egl;
        d.device = gpu->device;
        d.why = "auto: EGL finds a GPU";
      } else {
        d.renderer = Renderer::OsMesa;
        d.why = "auto: " + why_not;
      }
      break;
    }
  }
  // What the contexts will name themselves: a context of the renderer decided, so that a
  // renderer that cannot make one fails here, before any rendering.
  const GlInfo info = gl_info(d.renderer);
  d.gl_renderer = info.renderer;
  d.gl_version = info.version;
  g_process_renderer.store(d.renderer);
  return d;
}

GlContext::GlContext(int width, int height) : GlContext(width, height, process_renderer()) {}

GlContext::GlContext(int width, int height, Renderer renderer)
    : renderer_(renderer), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw std::runtime_error(fmt::format("GlContext: bad framebuffer size {}x{}", width, height));
  }
  buffer_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  surface_ = renderer == Renderer::Egl ? detail::egl_surface(width, height)
                                       : detail::osmesa_surface(buffer_.data(), width, height);
  make_current();
}

GlContext::~GlContext() {
  // Unbound first, so a later context allocated at the same address is never mistaken for
  // current.
  if (t_current == this) {
    surface_->unbind();
    t_current = nullptr;
    t_surface = nullptr;
  }
}

void GlContext::make_current() {
  if (t_current == this && surface_->bound()) return;
  if (t_current != nullptr && t_current != this) t_surface->unbind();
  t_current = nullptr;
  t_surface = nullptr;
  surface_->bind();
  t_current = this;
  t_surface = surface_.get();
}

void GlContext::finish() {
  const Rect whole{0, 0, width_, height_};
  finish(std::span<const Rect>(&whole, 1));
}

void GlContext::finish(std::span<const Rect> regions) {
  for (const Rect& r : regions) {
    if (!r.empty() && (r.x < 0 || r.y < 0 || r.right() > width_ || r.bottom() > height_))
      throw std::out_of_range(
          fmt::format("GlContext::finish: region {}x{} at {},{} is outside "
                      "the {}x{} surface",
                      r.w, r.h, r.x, r.y, width_, height_));
  }
  make_current();
  surface_->finish(buffer_.data(), width_, height_, regions);
}

std::string GlInfo::mesa_version() const {
  const std::string marker = "Mesa ";
  const auto at = version.find(marker);
  if (at == std::string::npos) return {};
  const auto start = at + marker.size();
  return version.substr(start, version.find(' ', start) - start);
}

GlInfo gl_info() {
  return gl_info(process_renderer());
}

GlInfo gl_info(Renderer renderer) {
  GlContext context(1, 1, renderer);
  const auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl().GetString(name));
    return std::string(s ? s : "");
  };
  return {text(GL_VERSION), text(GL_RENDERER)};
}

}  // namespace l2
