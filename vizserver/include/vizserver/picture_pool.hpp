// Display pictures handed from one composed (or received) frame to the next. A frame's
// pictures are shared (FramePtr) with other threads and freed wherever the last holder lets go;
// freed, glibc gave their megabytes back to the kernel and every new frame's first writes
// faulted them in again, page by page, which showed in the vizserver path's profile. Shared
// through share(), a frame's pictures come back here instead, for the next frame of that size.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "image/rgb_image.hpp"
#include "vizserver/frame_assembler.hpp"

namespace l2::viz {

class PicturePool : public std::enable_shared_from_this<PicturePool> {
 public:
  // Keeps at most `max_kept` pictures (more given back are freed).
  static std::shared_ptr<PicturePool> make(std::size_t max_kept) {
    return std::shared_ptr<PicturePool>(new PicturePool(max_kept));
  }

  // A width x height picture, its pixels unset: one given back if there is one of that size.
  RgbImage take(int width, int height);
  // The frame, shared: when its last holder lets go, its pictures come back to this pool (or
  // are freed, once the pool is gone). Thread-safe.
  std::shared_ptr<const ComposedFrame> share(ComposedFrame frame);
  std::size_t kept() const;

 private:
  explicit PicturePool(std::size_t max_kept) : max_kept_(max_kept) {
    kept_.reserve(max_kept);  // give() runs in a deleter: it must not allocate
  }
  void give(std::vector<RgbImage>& pictures);

  std::size_t max_kept_;
  mutable std::mutex mutex_;
  std::vector<RgbImage> kept_;
};

}  // namespace l2::viz
