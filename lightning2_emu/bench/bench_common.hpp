// What the emulator benchmark's parts share (bench.cpp, bench_depth.cpp): timing in
// alternation against memcpy of the same bytes, and the frames a case routes.
#pragma once

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

#include "image/rgb_image.hpp"
#include "lightning2_emu/input_frame.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/worker_pool.hpp"
#include "pixel_copy.hpp"

namespace l2bench {

using Clock = std::chrono::steady_clock;

// One timed run: wall time, and CPU time of the whole process (every worker). On a shared
// machine the CPU time leaves out the time other processes held the cores, so it compares
// implementations more steadily than wall time does; it still counts memory stalls.
struct Time {
  double wall = 0, cpu = 0;
};

inline double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

template <class Fn>
Time timed(Fn&& fn) {
  const double cpu0 = process_cpu_seconds();
  const auto t0 = Clock::now();
  fn();
  return {std::chrono::duration<double>(Clock::now() - t0).count(), process_cpu_seconds() - cpu0};
}

// Run times of one figure over the repetitions.
struct Samples {
  std::vector<Time> runs;
  double best() const {
    double b = runs.front().wall;
    for (const Time& t : runs) b = std::min(b, t.wall);
    return b;
  }
  double median_cpu() const;
};

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline double Samples::median_cpu() const {
  std::vector<double> cpu;
  for (const Time& t : runs) cpu.push_back(t.cpu);
  return median(cpu);
}

// Median over the repetitions of baseline time / routing time, by wall or CPU time.
inline double median_ratio(const Samples& baseline, const Samples& routing, double Time::*field) {
  std::vector<double> ratios;
  for (std::size_t r = 0; r < routing.runs.size(); ++r) {
    ratios.push_back(baseline.runs[r].*field / (routing.runs[r].*field));
  }
  return median(ratios);
}

struct Built {
  std::vector<l2::RgbImage> frames;
  std::vector<l2::InputFrame> views;
  std::vector<std::size_t> input_bytes;  // strip bytes each input routes
  std::size_t routed_bytes = 0;
};

// One memcpy per input of the bytes it routes, from its frame into a display-sized buffer,
// spread over the pool by bytes.
class CopySameBytes {
 public:
  // streaming: the router's own copy (pixel_copy.hpp) instead of memcpy.
  CopySameBytes(const Built& b, l2::WorkerPool& pool, bool streaming)
      : pool_(pool), streaming_(streaming), dst_(b.routed_bytes), shares_(pool.workers()) {
    // Cut the per-input copies into equal shares, one per worker.
    const std::size_t share = (b.routed_bytes + pool.workers() - 1) / pool.workers();
    std::size_t out = 0;
    for (std::size_t i = 0; i < b.frames.size(); ++i) {
      std::size_t done = 0;
      while (done < b.input_bytes[i]) {
        const std::size_t w = out / share;
        const std::size_t n = std::min(b.input_bytes[i] - done, (w + 1) * share - out);
        shares_[w].push_back({b.frames[i].data() + done, dst_.data() + out, n});
        done += n;
        out += n;
      }
    }
  }
  void operator()() {
    pool_.run(pool_.workers(), [&](int task, int) {
      for (const Chunk& c : shares_[task]) {
        if (streaming_) {
          l2::pixel_copy::stream_bytes(c.dst, c.src, c.bytes);
        } else {
          std::memcpy(c.dst, c.src, c.bytes);
        }
      }
      l2::pixel_copy::finish_streaming();
    });
  }

 private:
  struct Chunk {
    const std::uint8_t* src;
    std::uint8_t* dst;
    std::size_t bytes;
  };
  l2::WorkerPool& pool_;
  bool streaming_;
  std::vector<std::uint8_t> dst_;
  std::vector<std::vector<Chunk>> shares_;
};

// Heap bytes in use now (malloc's own count, mmapped blocks included). The router's memory is
// the growth across its construction and first frames: resident size would not show it when it
// reuses pages an earlier scenario freed.
inline double heap_mib() {
  const struct mallinfo2 m = mallinfo2();
  return double(m.uordblks + m.hblkhd) / (1 << 20);
}

inline double gbps(std::size_t bytes, double seconds) {
  return double(bytes) / seconds / 1e9;
}

// The router's whole frame and a memcpy of the same bytes, timed in alternation (one warm-up
// pair first): the machine's bandwidth changes from second to second, so a ratio only means
// something between runs made in the same moments.
struct RouteAndCopy {
  Samples route, copy_same;
};
inline RouteAndCopy route_against_memcpy(l2::Router& router, const Built& b, l2::WorkerPool& pool,
                                         int repetitions) {
  CopySameBytes memcpy_same(b, pool, false);
  RouteAndCopy t;
  for (int r = -1; r < repetitions; ++r) {
    const Time route_t = timed([&] { router.route(b.views); });
    const Time memcpy_t = timed(memcpy_same);
    if (r < 0) continue;
    t.route.runs.push_back(route_t);
    t.copy_same.runs.push_back(memcpy_t);
  }
  return t;
}

// Depth compositing, sort-last and hybrid, at full coverage and at `coverage_percent`
// (bench_depth.cpp).
void run_compositing(int repetitions, int cores, int coverage_percent);

}  // namespace l2bench
