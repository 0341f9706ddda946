#include "lightning2_emu/worker_pool.hpp"

#include <algorithm>

namespace l2 {

WorkerPool::WorkerPool(int workers) {
  if (workers <= 0) workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads_.reserve(workers - 1);
  try {
    for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { thread_main(w); });
  } catch (...) {
    // The destructor does not run for a constructor that throws: without this the threads
    // started so far were joined while waiting for a stop that never came (a hang).
    stop();
    throw;
  }
}

WorkerPool::~WorkerPool() {
  stop();
}

void WorkerPool::stop() noexcept {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  threads_.clear();  // joins
}

void WorkerPool::run_erased(int tasks, TaskFn fn, void* ctx) {
  if (tasks <= 0) return;
  if (threads_.empty() || tasks == 1) {
    for (int t = 0; t < tasks; ++t) fn(ctx, t, 0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    fn_ = fn;
    ctx_ = ctx;
    tasks_ = tasks;
    next_.store(0, std::memory_order_relaxed);
    busy_ = static_cast<int>(threads_.size());
    ++batch_;
  }
  start_.notify_all();
  work(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return busy_ == 0; });
}

void WorkerPool::work(int worker) {
  for (int t = next_.fetch_add(1, std::memory_order_relaxed); t < tasks_;
       t = next_.fetch_add(1, std::memory_order_relaxed)) {
    fn_(ctx_, t, worker);
  }
}

void WorkerPool::thread_main(int worker) {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || batch_ != seen; });
      if (stopping_) return;
      seen = batch_;
    }
    work(worker);
    {
      std::lock_guard lock(mutex_);
      --busy_;
    }
    done_.notify_one();
  }
}

}  // namespace l2
