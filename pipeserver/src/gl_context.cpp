#include "pipeserver/gl_context.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <fmt/format.h>

#include <stdexcept>

namespace l2 {

struct GlContext::Impl {
  OSMesaContext context = nullptr;
};

GlContext::GlContext(int width, int height)
    : width_(width), height_(height), impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw std::runtime_error(fmt::format("GlContext: bad framebuffer size {}x{}", width, height));
  }
  buffer_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  impl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (impl_->context == nullptr)
    throw std::runtime_error("GlContext: OSMesaCreateContextExt failed");
  make_current();
}

GlContext::~GlContext() {
  if (impl_->context == nullptr) return;
  // Unbind first, so a later context allocated at the same address is never mistaken for current.
  if (OSMesaGetCurrentContext() == impl_->context) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(impl_->context);
}

void GlContext::make_current() {
  if (OSMesaGetCurrentContext() == impl_->context) return;
  if (!OSMesaMakeCurrent(impl_->context, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
    throw std::runtime_error(
        fmt::format("GlContext: OSMesaMakeCurrent failed for {}x{}", width_, height_));
  }
}

std::string GlInfo::mesa_version() const {
  const std::string marker = "Mesa ";
  const auto at = version.find(marker);
  if (at == std::string::npos) return {};
  const auto start = at + marker.size();
  return version.substr(start, version.find(' ', start) - start);
}

GlInfo gl_info() {
  GlContext context(1, 1);
  // Through OSMesa's own entry point: in a process that also links libGL (a GLFW window), the
  // plain glGetString symbol may resolve to libGL's, which knows no OSMesa context.
  const auto get_string =
      reinterpret_cast<const GLubyte* (*)(GLenum)>(OSMesaGetProcAddress("glGetString"));
  const auto text = [get_string](GLenum name) {
    const auto* s = get_string ? reinterpret_cast<const char*>(get_string(name)) : nullptr;
    return std::string(s ? s : "");
  };
  return {text(GL_VERSION), text(GL_RENDERER)};
}

}  // namespace l2
