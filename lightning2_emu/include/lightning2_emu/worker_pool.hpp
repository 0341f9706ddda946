// A small fixed pool of threads that runs "task 0..n-1" batches: created once, reused every
// frame, so routing never creates a thread per frame. The calling thread works too.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace l2 {

class WorkerPool {
 public:
  // workers <= 0: one per hardware thread. workers == 1: everything runs on the caller.
  // Throws std::system_error when a thread cannot be started, after ending those that were.
  explicit WorkerPool(int workers = 0);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int workers() const { return static_cast<int>(threads_.size()) + 1; }

  // Calls fn(task, worker) for every task in 0..tasks-1 and returns when all are done.
  // worker is 0..workers()-1 and names a scratch slot no other running task uses.
  // fn must not throw.
  template <class Fn>
  void run(int tasks, Fn&& fn) {
    auto trampoline = [](void* ctx, int task, int worker) {
      (*static_cast<std::remove_reference_t<Fn>*>(ctx))(task, worker);
    };
    run_erased(tasks, trampoline, &fn);
  }

 private:
  using TaskFn = void (*)(void*, int, int);
  void run_erased(int tasks, TaskFn fn, void* ctx);
  void work(int worker);
  void thread_main(int worker);
  void stop() noexcept;  // ends and joins every thread

  std::vector<std::jthread> threads_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::uint64_t batch_ = 0;  // bumped for every batch; threads wait for a change
  int busy_ = 0;             // threads still working on the current batch
  bool stopping_ = false;
  TaskFn fn_ = nullptr;
  void* ctx_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_{0};
};

}  // namespace l2
