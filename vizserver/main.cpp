// vizserver: the compositing server of the viz path (WireGL §4.2) as a
// process. Pipeservers connect with TileSender, send their rendered tiles, and this writes
// each composed frame's displays as PNG files.
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "command_line/options.hpp"
#include "command_line/parse.hpp"
#include "command_line/size_text.hpp"
#include "display_sender.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "swap_queue.hpp"
#include "vizserver/compositing_server.hpp"

namespace {

// Swapped frames waiting to be written or streamed; a slower writer holds the swaps back.
constexpr std::size_t kQueuedFrames = 4;

// "1280x1024,640x480" -> sizes; throws CLI::ValidationError naming the bad item.
std::vector<std::pair<int, int>> parse_displays(const std::string& text) {
  std::vector<std::pair<int, int>> sizes;
  for (const std::string& item : l2::list_items(text)) {
    const std::optional<l2::SizeText> size = l2::parse_size_text(item);
    const auto in_range = [](int side) { return side >= 1 && side <= l2::viz::kMaxDisplaySide; };
    if (!size || !in_range(size->width) || !in_range(size->height)) {
      throw CLI::ValidationError("--displays", fmt::format("'{}' is not WIDTHxHEIGHT (1..{} each)",
                                                           item, l2::viz::kMaxDisplaySide));
    }
    sizes.emplace_back(size->width, size->height);
  }
  return sizes;
}

// Where each swapped frame goes: PNG files, the display stream, a line in the log.
struct Outputs {
  std::string png_dir;                           // empty: no PNGs
  std::optional<l2::viz::DisplaySender> stream;  // --display-stream
  std::FILE* log = stdout;
};

void put_frame(Outputs& out, const l2::viz::ComposedFrame& frame) {
  if (!out.png_dir.empty()) {
    for (std::size_t d = 0; d < frame.displays.size(); ++d) {
      l2::write_png(fmt::format("{}/display-{}-frame-{}.png", out.png_dir, d, frame.frame),
                    frame.displays[d]);
    }
  }
  if (out.stream) out.stream->send_frame(frame);
  fmt::print(out.log, "swapped frame {}: {} tiles, {} clipped rows, {} rows for missing displays\n",
             frame.frame, frame.tiles, frame.counts.clips, frame.counts.missing_display);
  std::fflush(out.log);
}

// Hands `frames` swapped frames to `out`, in order. Throws NetError when the run fails first
// (the server's failure line), every pipeserver leaves early, or the watcher goes away.
void serve(l2::viz::CompositingServer& server, l2::viz::SwapQueue& queue, Outputs& out,
           int frames) {
  for (int written = 0; written < frames;) {
    // The watcher's verdicts first: a frame may wait for nothing but a lost pipeserver.
    if (out.stream) {
      for (const std::uint32_t lost : out.stream->take_lost())
        server.lose_pipeserver(static_cast<int>(lost));
    }
    const l2::viz::FramePtr frame = queue.pop(std::chrono::milliseconds(100));
    if (frame) {
      put_frame(out, *frame);
      ++written;
      continue;
    }
    // Whoever watches our displays has gone (l2wall ended): there is no one to compose for.
    if (out.stream && out.stream->watcher_gone()) {
      throw l2::NetError(fmt::format("{}: the watcher closed the connection after {} of {} frames",
                                     out.stream->peer(), written, frames));
    }
    // The loop hands over its last frames before it ends: look again once it has ended.
    if (server.wait_finished(std::chrono::milliseconds(0)) && queue.empty()) {
      if (const l2::Status failure = server.failure(); !failure.ok())
        throw l2::NetError(failure.reason());
      throw l2::NetError(
          fmt::format("every pipeserver disconnected after {} of {} frames", written, frames));
    }
  }
}

// The connections refused or closed on the way (strangers, misconfigured pipeservers): the
// first few, and how many in all.
void print_notes(const l2::viz::CompositingServer& server) {
  const std::vector<std::string> kept = server.errors();
  for (const std::string& e : kept) fmt::print(stderr, "vizserver: note: {}\n", e);
  if (server.error_count() > kept.size()) {
    fmt::print(stderr, "vizserver: note: ... and {} more ({} connections refused or closed)\n",
               server.error_count() - kept.size(), server.error_count());
  }
}

// Closes the queue when it goes out of scope: declared after the server, so it runs first
// and a server thread waiting in push() can always be stopped and joined.
struct QueueCloser {
  l2::viz::SwapQueue& queue;
  ~QueueCloser() { queue.close(); }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "vizserver: compositing server of the viz path (WireGL 4.2).\n"
      "Pipeservers connect over TCP (docs/vizserver-protocol.md), send the tiles they rendered "
      "and FRAME_DONE; when every pipeserver has finished a frame it is composed (higher "
      "pipeserver wins where tiles overlap, black background), written as "
      "DIR/display-<d>-frame-<k>.png and/or sent on the display stream, and SWAPPED goes back "
      "to every pipeserver.\n"
      "Prints 'listening on HOST:PORT' first (to --log FILE if given), then one line per swap. "
      "Exits 0 after --frames frames, 1 when the run fails (a pipeserver broke the protocol, "
      "died or went silent while a frame waited for it; the display stream's watcher went "
      "away), 2 on bad arguments.\n"
      "With L2_VIZ_TOKEN (32 hex digits) in the environment, a HELLO without that token is "
      "refused (l2wall run sets one for every run); without it any peer may say HELLO."};
  std::string displays_text, host = "127.0.0.1", out_dir, stream_address, log_path;
  int pipeservers = 1, frames = 1;
  int port = 0;
  long long accept_timeout_ms = 30000, stall_timeout_ms = 10000;
  app.add_option("--displays", displays_text, "Display sizes in display order: WxH[,WxH...]")
      ->required();
  app.add_option("--pipeservers", pipeservers, "Number of pipeservers that will connect")
      ->check(CLI::Range(1, 4096))
      ->required();
  // Named as `l2wall run` names the address it starts this server with.
  app.add_option("--viz-port", port, "TCP port to listen on; 0 picks a free one (printed)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  app.add_option("--viz-host", host, "Address to listen on (0.0.0.0 for every interface)")
      ->capture_default_str();
  app.add_option("--frames", frames, "Frames to compose and write before exiting")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
  l2::add_out_option(app, out_dir, "display-<d>-frame-<k>.png for every swapped frame");
  app.add_option("--display-stream", stream_address,
                 "HOST:PORT of a watcher (l2wall run) to connect to: LISTENING with the bound "
                 "port first, then every swapped frame's display pictures, ERROR before a "
                 "failed run exits (docs/vizserver-protocol.md)")
      ->check(l2::endpoint_error, "HOST:PORT");
  bool survive_loss = false;
  app.add_flag("--survive-loss", survive_loss,
               "a pipeserver whose connection closes early does not end the run: the watcher "
               "says on the display stream whether it is lost (LOST; frames then complete "
               "without it) or the run ends (l2wall run --survive-host-loss)")
      ->needs("--display-stream");
  app.add_option("--log", log_path, "Write the listening and per-swap lines here, not stdout");
  l2::add_timeout_option(app, "accept-timeout", accept_timeout_ms, true,
                         "for all pipeservers to connect; 0 waits forever");
  l2::add_timeout_option(app, "stall-timeout", stall_timeout_ms, true,
                         "a pipeserver may stay silent while a frame waits for it; 0: forever");
  std::vector<std::pair<int, int>> sizes;
  app.callback([&] {  // after parsing: a CLI::ValidationError here is a usage error too
    sizes = parse_displays(displays_text);
    if (out_dir.empty() && stream_address.empty()) {
      throw CLI::ValidationError("--out", "give --out, --display-stream or both");
    }
  });
  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;

  l2::viz::ServerOptions options;
  options.display_sizes = sizes;
  options.pipeservers = pipeservers;
  options.host = host;
  options.port = static_cast<std::uint16_t>(port);
  options.accept_timeout = std::chrono::milliseconds(accept_timeout_ms);
  options.stall_timeout = std::chrono::milliseconds(stall_timeout_ms);
  options.survive_losses = survive_loss;
  Outputs out;
  out.png_dir = out_dir;
  try {
    if (!log_path.empty()) {
      out.log = std::fopen(log_path.c_str(), "w");
      if (!out.log) {
        throw std::runtime_error(
            fmt::format("--log {}: cannot write: {}", log_path, std::strerror(errno)));
      }
    }
    options.token = l2::viz::token_from_environment();
    // The stream first, so that even a port we cannot bind reaches the watcher as ERROR.
    if (!stream_address.empty()) {
      const l2::Endpoint stream = l2::parse_endpoint(stream_address);
      out.stream.emplace(l2::viz::DisplaySender::connect(stream.host, stream.port));
    }
    // Before listening: a folder that cannot be made failed only at the first swap, after the
    // pipeservers had connected and been told frame 0 swapped.
    if (!out.png_dir.empty()) l2::make_folders(out.png_dir, "--out");
    l2::viz::CompositingServer server(options);
    l2::viz::SwapQueue queue(kQueuedFrames);
    const QueueCloser closer{queue};
    server.on_swap([&queue](const l2::viz::FramePtr& f) { queue.push(f); });
    server.start();
    if (out.stream) {
      out.stream->send_listening({server.port(), static_cast<std::uint32_t>(sizes.size()),
                                  static_cast<std::uint32_t>(pipeservers)});
    }
    fmt::print(out.log, "listening on {}:{}\n", host, server.port());
    std::fflush(out.log);
    serve(server, queue, out, frames);
    print_notes(server);
    return 0;
  } catch (const std::exception& e) {
    if (out.stream) out.stream->send_error(e.what());
    fmt::print(stderr, "vizserver: error: {}\n", e.what());
    return 1;
  }
}
