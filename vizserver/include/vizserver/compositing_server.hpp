// The compositing server of the viz path (WireGL §4.2): accepts the
// pipeservers, collects their tiles per frame, composes each frame into one image per display
// (FrameAssembler: spec §5 overlap rule, black background) and "swaps" it when every
// pipeserver has finished it, then sends SWAPPED to every pipeserver.
//
// One thread runs a poll() loop over the listening socket and all connections; it owns the
// sockets and the FrameAssembler. Callers only see swapped frames, which are immutable
// (shared_ptr<const>) and published under a mutex.
//
// Failures end the run with one line naming the pipeserver, its address and the frame: a
// pipeserver that breaks the protocol, disconnects or goes silent (stall_timeout) while a
// frame waits for it, or pipeservers that do not all say HELLO within accept_timeout. The
// server then sends that line as ERROR to every pipeserver and closes. A connection that never
// said HELLO and sends garbage, or says HELLO without the run's token, is closed and logged
// without ending the run: counted in error_count(), the first few kept in errors().
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/result.hpp"
#include "base/socket.hpp"
#include "image/rgb_image.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "viz_link/run_token.hpp"
#include "vizserver/frame_assembler.hpp"

namespace l2::viz {

struct ServerOptions {
  std::vector<std::pair<int, int>> display_sizes;   // width, height of each display
  int pipeservers = 1;                              // pipeservers expected
  std::string host = "127.0.0.1";                   // where to listen ("0.0.0.0": everywhere)
  std::uint16_t port = 0;                           // 0: pick a free port, see port()
  Rgb background{};                                 // pixels no tile writes (spec §5: black)
  std::chrono::milliseconds accept_timeout{30000};  // all HELLOs by then; 0: wait forever
  std::chrono::milliseconds stall_timeout{10000};   // silence while a frame waits; 0: never
  std::size_t recent_frames = 8;                    // swapped frames wait_frame can still find
  std::size_t max_buffered_bytes = std::size_t{1} << 30;  // tile bytes held for open frames
  RunToken token{};  // a HELLO without it is refused (run_token.hpp); all zero: none needed
  // A pipeserver's connection closing early does not end the run: it awaits lose_pipeserver()
  // (l2wall run --survive-host-loss decides), and frames then complete without it.
  bool survive_losses = false;
};

using FramePtr = std::shared_ptr<const ComposedFrame>;

inline constexpr std::size_t kKeptErrors = 16;

class ServerLoop;     // the poll() thread (src/server_loop.hpp)
struct ServerShared;  // what it publishes to callers, under a mutex

class CompositingServer {
 public:
  // Binds and listens (throws NetError); no thread runs until start().
  explicit CompositingServer(ServerOptions options);
  ~CompositingServer();  // stop()
  CompositingServer(const CompositingServer&) = delete;
  CompositingServer& operator=(const CompositingServer&) = delete;

  std::uint16_t port() const { return port_; }
  const ServerOptions& options() const { return options_; }

  // Called on the server thread for every swapped frame, in frame order, none missed. Set it
  // before start(); keep it short (it holds up the network loop).
  void on_swap(std::function<void(const FramePtr&)> callback);
  void start();
  // Ends the loop and closes every connection. Idempotent.
  void stop();
  // Pipeserver `pipeserver` is gone (survive_losses): its connection, if any, is closed and no
  // frame waits for it from now on; frames waiting only for it are swapped. Any thread; after
  // start().
  void lose_pipeserver(int pipeserver);

  // The displays of `frame` once it is swapped. Throws NetError when the run failed (the
  // failure line), every pipeserver left without sending it, it is older than the recent
  // frames (recent_frames), or `timeout` passed.
  FramePtr wait_frame(std::uint32_t frame, std::chrono::milliseconds timeout);
  // Blocks until the loop ends (all pipeservers done, failure, or stop) or timeout; true if it
  // ended.
  bool wait_finished(std::chrono::milliseconds timeout);

  // Failed, with the line that ended the run, once one did; ok while it runs or ended well.
  Status failure() const;
  // The first kKeptErrors connection errors, and the failure; error_count() counts them all,
  // so that a flood of strangers costs a number, not a line each.
  std::vector<std::string> errors() const;
  std::uint64_t error_count() const;
  StripErrorCounts counts() const;  // clips and missing displays of all frames
  std::optional<std::uint32_t> last_swapped() const;

 private:
  ServerOptions options_;
  Fd listener_;  // handed to the loop by start()
  std::uint16_t port_ = 0;
  std::function<void(const FramePtr&)> on_swap_;
  std::shared_ptr<ServerShared> shared_;
  std::unique_ptr<ServerLoop> loop_;
};

}  // namespace l2::viz
