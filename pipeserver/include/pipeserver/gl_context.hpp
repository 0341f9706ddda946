// One off-screen OpenGL context through OSMesa (Mesa's software rasteriser), rendering into a
// caller-visible RGBA buffer with a 24-bit depth buffer. A pipeserver owns exactly one; the
// reference render owns its own so it never disturbs a pipeserver's framebuffer.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace l2 {

class GlContext {
 public:
  // Throws std::runtime_error when OSMesa cannot create or bind the context.
  GlContext(int width, int height);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds this context and its buffer to the calling thread. Cheap when already current.
  void make_current();

  int width() const { return width_; }
  int height() const { return height_; }
  // RGBA, 4 bytes a pixel, rows bottom to top (OpenGL's origin). Valid after glFinish().
  const std::uint8_t* rgba() const { return buffer_.data(); }

 private:
  struct Impl;
  int width_, height_;
  std::vector<std::uint8_t> buffer_;
  std::unique_ptr<Impl> impl_;
};

// The OpenGL implementation the contexts render with, as it names itself. Rendered pixels
// depend on it (rasterisation rounding changes between Mesa and LLVM versions, and with the
// CPU's vector width), so golden images of rendered scenes record it.
struct GlInfo {
  std::string version;   // GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6"
  std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  // The Mesa release named in `version` ("22.3.6"); empty when it names none.
  std::string mesa_version() const;
};

// Asks a 1x1 context of its own. Throws std::runtime_error when OSMesa cannot create one.
GlInfo gl_info();

}  // namespace l2
