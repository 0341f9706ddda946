// One off-screen OpenGL context through OSMesa (Mesa's software rasteriser), rendering into a
// caller-visible RGBA buffer with a 24-bit depth buffer. A pipeserver owns exactly one; the
// reference render owns its own so it never disturbs a pipeserver's framebuffer.
#pragma once

#include <cstdint>
#include <memory>
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

}  // namespace l2
