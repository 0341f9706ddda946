// `pipeserver --live`: one pipeserver of a live run (l2wall run). It renders frames 0..N-1, writes
// each into its DVI link (POSIX shared memory) and, from the second frame on, waits for the
// READY of the previous frame on its serial back-channel before publishing (spec §6.1).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "balance/control_channel.hpp"
#include "dvi_link/dvi_link.hpp"
#include "dvi_link/frame_delta.hpp"
#include "pipeserver/live_exit.hpp"
#include "pipeserver/renderer_choice.hpp"
#include "pipeserver/scene.hpp"
#include "sync_backchannel/ready_channel.hpp"
#include "tilelayout/tile_layout.hpp"
#include "viz_link/tile_sender.hpp"

namespace l2 {

// Where a pipeserver's tiles go on the viz path: a compositing server over TCP
// (viz::TileSender), or the board columns owning their displays over MPI.
class TileSink {
 public:
  virtual ~TileSink() = default;
  virtual void send_tile(std::uint32_t frame, const viz::TileTarget& tile, const std::uint8_t* rgb,
                         std::size_t stride) = 0;
  virtual void finish_frame(std::uint32_t frame, std::uint32_t tiles_sent) = 0;
  // Throws (NetError for the compositing server) when `frame` is not swapped in time.
  virtual void wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout) = 0;
};

// A TileSink of any sender with these three calls.
template <typename Sender>
class TileSinkOf final : public TileSink {
 public:
  explicit TileSinkOf(Sender sender) : sender_(std::move(sender)) {}
  void send_tile(std::uint32_t frame, const viz::TileTarget& tile, const std::uint8_t* rgb,
                 std::size_t stride) override {
    sender_.send_tile(frame, tile, rgb, stride);
  }
  void finish_frame(std::uint32_t frame, std::uint32_t tiles_sent) override {
    sender_.finish_frame(frame, tiles_sent);
  }
  void wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout) override {
    sender_.wait_swapped(frame, timeout);
  }

 private:
  Sender sender_;
};

// The DVI link a pipeserver publishes its frames on and the back-channel its READYs come on: shared
// memory and a serial line on one machine, MPI messages in a run across machines. Made once,
// where the pipeserver starts.
struct LiveLinks {
  std::shared_ptr<void> keeps;  // what the two use, so it outlives them (the serial port)
  std::unique_ptr<DviSender> link;
  std::unique_ptr<ReadyChannel> channel;
  std::unique_ptr<TileSink> tiles;  // the viz path over MPI; else --viz
};
using MakeLiveLinks =
    std::function<LiveLinks(const TileLayout& layout, const PipeserverPlan& plan)>;

// The shared-memory link `link` and the serial line `backchannel` (l2wall run on one machine).
MakeLiveLinks shared_memory_links(const std::string& link, const std::string& backchannel);

struct LiveOptions {
  std::string wall;  // empty: the built-in default wall
  int pipeserver = 0;
  std::string scene = "mesh";
  SceneOptions scene_options;
  // What renders the OpenGL (--renderer): decided as the pipeserver starts, and said in the
  // report's first line ("renderer egl (...)").
  RendererChoice renderer = RendererChoice::Auto;
  int frames = 10;
  std::string link;         // shared-memory name this pipeserver creates ("/l2-..."); empty: none
  std::string backchannel;  // serial device (a pty slave) the READYs arrive on (with link)
  MakeLiveLinks links;      // how the link and back-channel are made; empty: none (--viz only)
  std::string viz;          // "host:port" of a compositing server to send tiles to; empty: none
  // Frames over MPI and tiles to the compositing server (frame_delta.hpp); none: auto (tiles
  // to --viz whole, as TILE messages).
  std::optional<LinkCodec> link_codec;
  std::string
      report;  // file: the renderer decided on, then one line per frame (render and wait times)
  int ready_timeout_ms = 200;
  int ready_retries = 3;
  // Load balancing (balance/): after each frame the tiles' render times go out as TIMES, and
  // frame k+1 is rendered in the layout of the LAYOUT k+1 that comes back. Empty: the wall's
  // layout every frame.
  std::shared_ptr<ControlChannel> control;
  // A session run's windows (--windows-fd): WANT out before each READY wait, WINDOWS in for the
  // next frame after it, so every pipeserver moves a window in the same frame.
  std::shared_ptr<ControlChannel> windows;
};

// Every frame carries its frame number in the first pixel of the pipeserver's first tile (24 bits,
// R low byte), so the run can tell from the displays which frame they show.
inline constexpr int kStampBits = 24;

// Returns the process exit code: 0 on success, kExitNoReady when READY never came (message on
// stderr). Throws NetError when the compositing server is lost (kExitLostCompositingServer).
int run_live_mode(const LiveOptions& options);

}  // namespace l2
