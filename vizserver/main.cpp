// vizserver: the compositing server of the visualization-server path (WireGL §4.2) as a
// process. Pipeservers connect with TileSender, send their rendered tiles, and this writes
// each composed frame's displays as PNG files.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "image/png_io.hpp"
#include "vizserver/compositing_server.hpp"

namespace {

// "1280x1024,640x480" -> sizes; throws CLI::ValidationError naming the bad item.
std::vector<std::pair<int, int>> parse_displays(const std::string& text) {
  std::vector<std::pair<int, int>> sizes;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(item.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
        w < 1 || h < 1 || w > 16384 || h > 16384) {
      throw CLI::ValidationError("--displays",
                                 fmt::format("'{}' is not WIDTHxHEIGHT (1..16384 each)", item));
    }
    sizes.emplace_back(w, h);
    start = comma + 1;
  }
  return sizes;
}

// Frames handed over by the server thread, written by the main thread: no frame is lost
// however slowly PNGs are written.
struct FrameQueue {
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<l2::viz::FramePtr> frames;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "vizserver: compositing server of the visualization-server path (WireGL 4.2).\n"
      "Pipeservers connect over TCP (docs/vizserver-protocol.md), send the tiles they rendered "
      "and FRAME_DONE; when every pipeserver has finished a frame it is composed (higher "
      "pipeserver wins where tiles overlap, black background), written as "
      "DIR/display-<d>-frame-<k>.png, and SWAPPED goes back to every pipeserver.\n"
      "Prints 'listening on HOST:PORT' first, then one line per swap. Exits 0 after --frames "
      "frames, 1 when the run fails (a pipeserver broke the protocol, died or went silent "
      "while a frame waited for it), 2 on bad arguments."};
  std::string displays_text, host = "127.0.0.1", out_dir;
  int servers = 1, frames = 1;
  int port = 0;
  double accept_timeout = 30, stall_timeout = 10;
  app.add_option("--displays", displays_text, "Display sizes in display order: WxH[,WxH...]")
      ->required();
  app.add_option("--servers", servers, "Number of pipeservers that will connect")
      ->check(CLI::Range(1, 4096))
      ->required();
  app.add_option("--port", port, "TCP port to listen on; 0 picks a free one (printed)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  app.add_option("--host", host, "Address to listen on (0.0.0.0 for every interface)")
      ->capture_default_str();
  app.add_option("--frames", frames, "Frames to compose and write before exiting")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
  app.add_option("--out", out_dir, "Folder for display-<d>-frame-<k>.png")->required();
  app.add_option("--accept-timeout", accept_timeout,
                 "Seconds for all pipeservers to connect; 0 waits forever")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--stall-timeout", stall_timeout,
                 "Seconds a pipeserver may stay silent while a frame waits for it; 0: forever")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  std::vector<std::pair<int, int>> sizes;
  try {
    app.parse(argc, argv);
    sizes = parse_displays(displays_text);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  l2::viz::ServerOptions options;
  options.display_sizes = sizes;
  options.servers = servers;
  options.host = host;
  options.port = static_cast<std::uint16_t>(port);
  options.accept_timeout = std::chrono::milliseconds(static_cast<long long>(accept_timeout * 1000));
  options.stall_timeout = std::chrono::milliseconds(static_cast<long long>(stall_timeout * 1000));
  try {
    l2::viz::CompositingServer server(options);
    FrameQueue queue;
    server.on_swap([&queue](const l2::viz::FramePtr& f) {
      {
        std::lock_guard lock(queue.mutex);
        queue.frames.push_back(f);
      }
      queue.ready.notify_one();
    });
    server.start();
    fmt::print("listening on {}:{}\n", host, server.port());
    std::fflush(stdout);
    for (int written = 0; written < frames;) {
      l2::viz::FramePtr frame;
      {
        std::unique_lock lock(queue.mutex);
        queue.ready.wait_for(lock, std::chrono::milliseconds(100),
                             [&] { return !queue.frames.empty(); });
        if (!queue.frames.empty()) {
          frame = queue.frames.front();
          queue.frames.pop_front();
        }
      }
      if (!frame) {
        // The loop hands over its last frames before it ends: look again once it has ended.
        const bool ended = server.wait_finished(std::chrono::milliseconds(0));
        const bool more = [&] {
          std::lock_guard lock(queue.mutex);
          return !queue.frames.empty();
        }();
        if (ended && !more) {
          if (auto failure = server.failure()) throw l2::viz::VizError(*failure);
          throw l2::viz::VizError(
              fmt::format("every pipeserver disconnected after {} of {} frames", written, frames));
        }
        continue;
      }
      for (std::size_t d = 0; d < frame->displays.size(); ++d) {
        l2::write_png(fmt::format("{}/display-{}-frame-{}.png", out_dir, d, frame->frame),
                      frame->displays[d]);
      }
      fmt::print("swapped frame {}: {} tiles, {} clipped rows, {} rows for missing displays\n",
                 frame->frame, frame->tiles, frame->counts.clips, frame->counts.missing_display);
      std::fflush(stdout);
      ++written;
    }
    for (const std::string& e : server.errors()) fmt::print(stderr, "vizserver: note: {}\n", e);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "vizserver: error: {}\n", e.what());
    return 1;
  }
}
