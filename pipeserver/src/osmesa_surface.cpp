// OSMesa behind GlContext: a context drawing into the GlContext's own RGBA buffer. libOSMesa is
// loaded by name (RTLD_LOCAL), not linked: it exports every gl* entry point itself, which in a
// process that also holds EGL (glvnd's libEGL) or a window's libGL would take over the plain gl*
// symbols of everything else, and reach only OSMesa's contexts. Its functions, GL's included,
// are reached through the handle alone.
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <fmt/format.h>

#include <mutex>
#include <stdexcept>

#include "gl_surface.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2::detail {
namespace {

// OSMesa's entry points, from the library loaded once a process.
struct OsMesa {
  decltype(&::OSMesaCreateContextExt) create = nullptr;
  decltype(&::OSMesaDestroyContext) destroy = nullptr;
  decltype(&::OSMesaMakeCurrent) make_current = nullptr;
  decltype(&::OSMesaGetCurrentContext) current = nullptr;
  decltype(&::OSMesaGetProcAddress) proc = nullptr;
};

// The library's names, newest first: Debian 12's libosmesa6 installs libOSMesa.so.8.
constexpr const char* kLibraries[] = {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};

const OsMesa& osmesa() {
  static OsMesa api;
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = nullptr;
    std::string tried;
    for (const char* name : kLibraries) {
      handle = ::dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (handle != nullptr) break;
      tried += fmt::format("{}{}", tried.empty() ? "" : "; ", ::dlerror());
    }
    if (handle == nullptr) {
      error = "osmesa: cannot load libOSMesa (Debian: libosmesa6): " + tried;
      return;
    }
    // Never closed: LeakSanitizer names OSMesa's never-freed records by the library they came
    // from, and the contexts outlive every caller.
    const auto load = [&](auto& member, const char* name) {
      void* p = ::dlsym(handle, name);
      if (p == nullptr && error.empty()) error = fmt::format("osmesa: libOSMesa has no {}", name);
      member = reinterpret_cast<std::remove_reference_t<decltype(member)>>(p);
    };
    load(api.create, "OSMesaCreateContextExt");
    load(api.destroy, "OSMesaDestroyContext");
    load(api.make_current, "OSMesaMakeCurrent");
    load(api.current, "OSMesaGetCurrentContext");
    load(api.proc, "OSMesaGetProcAddress");
  });
  if (!error.empty()) throw RendererError(error);
  return api;
}

class OsMesaSurface final : public GlSurface {
 public:
  OsMesaSurface(std::uint8_t* rgba, int width, int height)
      : os_(osmesa()), rgba_(rgba), width_(width), height_(height) {
    // RGBA, a 24-bit depth buffer, no stencil or accumulation buffer.
    context_ = os_.create(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (context_ == nullptr) throw RendererError("osmesa: OSMesaCreateContextExt failed");
    load_api("osmesa");
  }
  ~OsMesaSurface() override {
    if (bound()) os_.make_current(nullptr, nullptr, 0, 0, 0);
    os_.destroy(context_);
  }
  OsMesaSurface(const OsMesaSurface&) = delete;
  OsMesaSurface& operator=(const OsMesaSurface&) = delete;

  void bind() override {
    if (!os_.make_current(context_, rgba_, GL_UNSIGNED_BYTE, width_, height_)) {
      throw std::runtime_error(
          fmt::format("osmesa: OSMesaMakeCurrent failed for {}x{}", width_, height_));
    }
  }
  void unbind() override {
    if (bound()) os_.make_current(nullptr, nullptr, 0, 0, 0);
  }
  bool bound() const override { return os_.current() == context_; }
  // OSMesa copies its rendering into the buffer it was bound with as GL finishes.
  void finish(std::uint8_t*, int, int, std::span<const Rect>) override { api_.Finish(); }
  void* proc(const char* name) const override { return reinterpret_cast<void*>(os_.proc(name)); }

 private:
  const OsMesa& os_;
  std::uint8_t* rgba_;
  int width_, height_;
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<GlSurface> osmesa_surface(std::uint8_t* rgba, int width, int height) {
  return std::make_unique<OsMesaSurface>(rgba, width, height);
}

}  // namespace l2::detail
