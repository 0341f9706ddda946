#include "vizserver/picture_pool.hpp"

#include <algorithm>

namespace l2::viz {

RgbImage PicturePool::take(int width, int height) {
  {
    std::lock_guard lock(mutex_);
    const auto it = std::find_if(kept_.begin(), kept_.end(), [&](const RgbImage& p) {
      return p.width() == width && p.height() == height;
    });
    if (it != kept_.end()) {
      RgbImage out = std::move(*it);
      *it = std::move(kept_.back());
      kept_.pop_back();
      return out;
    }
  }
  return RgbImage::unfilled(width, height);
}

void PicturePool::give(std::vector<RgbImage>& pictures) {
  std::lock_guard lock(mutex_);
  for (RgbImage& p : pictures) {
    if (kept_.size() >= max_kept_) return;
    kept_.push_back(std::move(p));
  }
}

std::size_t PicturePool::kept() const {
  std::lock_guard lock(mutex_);
  return kept_.size();
}

std::shared_ptr<const ComposedFrame> PicturePool::share(ComposedFrame frame) {
  // The deleter holds the pool weakly: a frame may outlive it (the watcher that received it).
  std::weak_ptr<PicturePool> pool = weak_from_this();
  return std::shared_ptr<const ComposedFrame>(
      new ComposedFrame(std::move(frame)), [pool](const ComposedFrame* f) {
        std::unique_ptr<ComposedFrame> owned(const_cast<ComposedFrame*>(f));
        if (const auto p = pool.lock()) p->give(owned->displays);
      });
}

}  // namespace l2::viz
