// Routing throughput against memcpy of the same bytes, measured in the same run, and the frame
// rate of the Lightning-2 headline case (WireGL figure 9: one 3200x2400 output fed by 12 inputs
// of 1280x1024; the hardware held 90 Hz). Prints peak memory.
//
//   lightning2_emu_bench [repetitions]
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "frame_builder.hpp"
#include "lightning2_emu/router.hpp"

namespace {

using Clock = std::chrono::steady_clock;

template <class Fn>
double median_seconds(int repetitions, Fn&& fn) {
  fn();  // warm-up: first-touch page faults, vector growth
  std::vector<double> times;
  for (int r = 0; r < repetitions; ++r) {
    const auto t0 = Clock::now();
    fn();
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

struct Scenario {
  const char* name;
  std::vector<l2::DisplaySpec> displays;
  int inputs;
  int tile_w, tile_h;
};

struct Built {
  std::vector<l2::RgbImage> frames;
  std::vector<l2::InputFrame> views;
  std::size_t routed_bytes = 0;
};

// Tiles cover every display; round-robin over the inputs; packed per spec §4.
Built build(const Scenario& s) {
  std::vector<std::vector<l2::testing::Tile>> tiles(s.inputs);
  int n = 0;
  Built b;
  for (const auto& d : s.displays) {
    for (int y = 0; y < d.height; y += s.tile_h) {
      for (int x = 0; x < d.width; x += s.tile_w) {
        tiles[n++ % s.inputs].push_back(
            {d.id, x, y, std::min(s.tile_w, d.width - x), std::min(s.tile_h, d.height - y)});
      }
    }
    b.routed_bytes += static_cast<std::size_t>(d.width) * d.height * 3;
  }
  for (int i = 0; i < s.inputs; ++i) {
    b.frames.emplace_back(1280, 1024);
    if (!l2::testing::pack_frame(tiles[i], false, b.frames.back())) {
      fmt::print(stderr, "{}: tiles do not fit input {}\n", s.name, i);
      std::exit(1);
    }
  }
  for (const auto& f : b.frames) b.views.push_back(l2::InputFrame::of(f));
  return b;
}

// memcpy of `bytes` split over `threads` threads (the same split a pool would make).
double memcpy_seconds(std::size_t bytes, int threads, int repetitions) {
  std::vector<std::uint8_t> src(bytes, 1), dst(bytes, 0);
  return median_seconds(repetitions, [&] {
    std::vector<std::jthread> pool;
    const std::size_t part = bytes / threads;
    for (int t = 1; t < threads; ++t) {
      pool.emplace_back([&, t] {
        const std::size_t end = t + 1 == threads ? bytes : part * (t + 1);
        std::memcpy(dst.data() + part * t, src.data() + part * t, end - part * t);
      });
    }
    std::memcpy(dst.data(), src.data(), part);
  });
}

double gbps(std::size_t bytes, double seconds) {
  return double(bytes) / seconds / 1e9;
}

void run(const Scenario& s, int repetitions, int cores) {
  const Built b = build(s);
  double route_s[2] = {};
  const int workers[2] = {1, cores};
  for (int k = 0; k < 2; ++k) {
    l2::WorkerPool pool(workers[k]);
    l2::Router router(l2::Mesh::fit(s.inputs, static_cast<int>(s.displays.size())), s.displays,
                      pool);
    route_s[k] = median_seconds(repetitions, [&] { router.route(b.views); });
    // The benchmark only counts if the routing is right.
    for (const auto& d : s.displays) {
      if (router.display(router.index_of_display(d.id)).back() !=
          l2::testing::pattern_image(d.id, d.width, d.height)) {
        fmt::print(stderr, "{}: display {} routed wrong\n", s.name, d.id);
        std::exit(1);
      }
    }
  }
  const double memcpy_s[2] = {memcpy_seconds(b.routed_bytes, 1, repetitions),
                              memcpy_seconds(b.routed_bytes, cores, repetitions)};
  fmt::print("\n{}: {} inputs of 1280x1024 -> {} display(s), tiles {}x{}, {:.1f} MB per frame\n",
             s.name, s.inputs, s.displays.size(), s.tile_w, s.tile_h, double(b.routed_bytes) / 1e6);
  for (int k = 0; k < 2; ++k) {
    fmt::print(
        "  {} worker(s): routing {:6.2f} GB/s ({:6.1f} frames/s)   memcpy {:6.2f} GB/s"
        "   routing/memcpy = {:.2f}\n",
        workers[k], gbps(b.routed_bytes, route_s[k]), 1.0 / route_s[k],
        gbps(b.routed_bytes, memcpy_s[k]), memcpy_s[k] / route_s[k]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(3, std::atoi(argv[1])) : 31;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  fmt::print("lightning2_emu_bench: {} cores, median of {} runs per figure\n", cores, repetitions);

  const Scenario headline{"headline (WireGL fig. 9)", {{0, 3200, 2400, 0}}, 12, 200, 200};
  run(headline, repetitions, cores);

  // The same routing on all cores, reported as the headline figures.
  {
    const Built b = build(headline);
    l2::WorkerPool pool(cores);
    l2::Router router(l2::Mesh::fit(12, 1), headline.displays, pool);
    const double s = median_seconds(repetitions, [&] { router.route(b.views); });
    const double m = memcpy_seconds(b.routed_bytes, cores, repetitions);
    fmt::print(
        "\nHEADLINE routing {:.2f} GB/s, memcpy {:.2f} GB/s, ratio {:.2f} (target 0.7, "
        "aim 0.9)\n",
        gbps(b.routed_bytes, s), gbps(b.routed_bytes, m), m / s);
    fmt::print(
        "HEADLINE 3200x2400 from 12 inputs: {:.1f} frames/s = {:.2f}x the hardware's "
        "90 Hz (target 1.0, aim 2.0)\n",
        1.0 / s, 1.0 / s / 90.0);
  }

  // Many small strips: per-strip cost shows here.
  const Scenario wall{
      "wall of 4 displays, small tiles",
      {{0, 1600, 1200, 0}, {1, 1600, 1200, 0}, {2, 1600, 1200, 0}, {3, 1600, 1200, 0}},
      8,
      64,
      48};
  run(wall, repetitions, cores);

  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  fmt::print("\npeak memory (max RSS): {:.1f} MB\n", double(usage.ru_maxrss) / 1024.0);
  return 0;
}
