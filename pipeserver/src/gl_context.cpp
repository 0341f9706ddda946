#include "pipeserver/gl_context.hpp"

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

}  // namespace l2
