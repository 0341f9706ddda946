// Swapped frames handed from the compositing server's thread (on_swap) to the thread that
// writes them out (PNG files, the display stream), in order, none lost. Bounded: a full queue
// holds up the server thread, and with it the SWAPPED its pipeservers wait for, so a slow
// consumer slows the run down instead of growing memory without limit.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>

#include "vizserver/compositing_server.hpp"

namespace l2::viz {

class SwapQueue {
 public:
  explicit SwapQueue(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  // Server thread: waits while the queue is full, unless it was closed (then nothing waits).
  void push(const FramePtr& frame);
  // Consumer: the oldest frame, or nullptr when none came within `timeout`.
  FramePtr pop(std::chrono::milliseconds timeout);
  // The consumer is leaving: push() no longer waits, so the server thread can always stop.
  void close();
  bool empty() const;

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<FramePtr> frames_;
  bool closed_ = false;
};

}  // namespace l2::viz
