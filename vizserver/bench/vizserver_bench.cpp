// How slow is the slow path? One 1280x1024 frame per iteration from one pipeserver thread to
// the compositing server over loopback (send, compose, SWAPPED), against memcpy of the same
// bytes measured in the same run: compare the bytes_per_second figures.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <vector>

#include "image/rgb_image.hpp"
#include "viz_link/tile_sender.hpp"
#include "vizserver/compositing_server.hpp"

namespace {

constexpr int kW = 1280, kH = 1024;

void BM_MemcpyFrame(benchmark::State& state) {
  const l2::RgbImage src(kW, kH, l2::Rgb{1, 2, 3});
  l2::RgbImage dst(kW, kH);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), src.bytes().size());
    benchmark::DoNotOptimize(dst.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(src.bytes().size()));
}
BENCHMARK(BM_MemcpyFrame);

// tiles = state.range(0): the frame cut into that many horizontal bands, sent from inside a
// framebuffer two pixels wider (row spans, as a pipeserver sends them).
void BM_LoopbackFrame(benchmark::State& state) {
  const int bands = static_cast<int>(state.range(0));
  l2::viz::ServerOptions o;
  o.display_sizes = {{kW, kH}};
  o.recent_frames = 1;
  l2::viz::CompositingServer server(o);
  server.start();
  auto sender = l2::viz::TileSender::connect("127.0.0.1", server.port(), 0, 1);
  const l2::RgbImage fb(kW + 2, kH, l2::Rgb{9, 8, 7});
  std::uint32_t frame = 0;
  for (auto _ : state) {
    for (int b = 0; b < bands; ++b) {
      const int y0 = kH * b / bands, y1 = kH * (b + 1) / bands;
      sender.send_tile(frame, {0, 0, y0, kW, y1 - y0}, fb.data() + y0 * fb.stride() + 6,
                       fb.stride());
    }
    sender.finish_frame(frame, static_cast<std::uint32_t>(bands));
    sender.wait_swapped(frame, std::chrono::seconds(10));
    ++frame;
  }
  state.SetBytesProcessed(state.iterations() * std::int64_t{kW} * kH * 3);
}
BENCHMARK(BM_LoopbackFrame)->Arg(1)->Arg(16)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
