#include "swap_queue.hpp"

namespace l2::viz {

void SwapQueue::push(const FramePtr& frame) {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return frames_.size() < capacity_ || closed_; });
    frames_.push_back(frame);
  }
  changed_.notify_all();
}

FramePtr SwapQueue::pop(std::chrono::milliseconds timeout) {
  FramePtr frame;
  {
    std::unique_lock lock(mutex_);
    if (!changed_.wait_for(lock, timeout, [&] { return !frames_.empty(); })) return nullptr;
    frame = std::move(frames_.front());
    frames_.pop_front();
  }
  changed_.notify_all();
  return frame;
}

void SwapQueue::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

bool SwapQueue::empty() const {
  std::lock_guard lock(mutex_);
  return frames_.empty();
}

}  // namespace l2::viz
