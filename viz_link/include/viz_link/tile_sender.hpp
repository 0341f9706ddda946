// The pipeserver's end of the viz path (WireGL §4.2): after rendering, send
// each tile's pixels straight from the framebuffer to the compositing server, say when the
// frame is complete, and wait for the server's SWAPPED to pace the next frame.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "base/socket.hpp"
#include "viz_link/run_token.hpp"
#include "viz_link/tile_delta.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz {

// Where a tile goes: a rectangle of one output display (the fields of l2::DisplayTile's
// display and on_display, kept plain so this library does not depend on tilelayout).
struct TileTarget {
  int display = 0;
  int x = 0, y = 0, w = 0, h = 0;
  TileKind how = TileKind::Copy;  // KEY and DEPTH go as TILE_EXT (spec §7)
  std::uint32_t key = 0;          // KEY: the key colour
};

struct SenderOptions {
  // Retries until the server listens, and reconnects while a server closes us before WELCOME
  // without a reason (it was flooded with connections and made room).
  std::chrono::milliseconds connect_timeout{5000};
  std::chrono::milliseconds io_timeout{10000};  // one send or the WELCOME, at most
  RunToken token{};                             // the run's token, sent in HELLO
  // Tiles as TILE_DELTA, what changed since their last frame (tile_delta.hpp); none: whole.
  std::optional<LinkCodec> codec;
};

class TileSender {
 public:
  // Connects, says HELLO and waits for WELCOME. Throws NetError: unreachable server, or the
  // server's refusal (wrong display count or token, pipeserver id taken or out of range).
  static TileSender connect(const std::string& host, std::uint16_t port, int pipeserver_id,
                            int display_count, SenderOptions options = {});

  // Sends one tile: h rows of w RGB pixels, row r starting at rgb + r * stride (stride in
  // bytes, so a tile inside a bigger framebuffer goes out row span by row span, uncopied); a
  // DEPTH tile's rows are 2w pixels, its depth right after its colour as packed (spec §7).
  // Throws std::invalid_argument for sides outside 1..4095, NetError if the server is gone.
  void send_tile(std::uint32_t frame, const TileTarget& tile, const std::uint8_t* rgb,
                 std::size_t stride);
  // This pipeserver's part of `frame` is complete: tiles_sent tiles went out for it.
  void finish_frame(std::uint32_t frame, std::uint32_t tiles_sent);
  // Blocks until the server has swapped `frame` (or a later one). Throws NetError on timeout,
  // on an ERROR from the server (its text included) or when the server is gone.
  void wait_swapped(std::uint32_t frame, std::chrono::milliseconds timeout);

  std::optional<std::uint32_t> last_swapped() const { return last_swapped_; }
  int pipeserver_id() const { return pipeserver_id_; }
  // "compositing server 127.0.0.1:5000", the prefix of every error.
  const std::string& peer() const { return peer_; }
  int fd() const { return fd_.get(); }

 private:
  TileSender(Fd fd, std::string peer, int pipeserver_id, SenderOptions options);
  // Says HELLO and reads until WELCOME. False when the server closed without a word first.
  bool say_hello(int display_count);
  // Reads one server message and records it. Throws NetError on ERROR (text kept) or EOF.
  void read_message(Clock::time_point deadline, const char* waiting_for);
  void send(std::span<const iovec> parts);

  Fd fd_;
  std::string peer_;
  int pipeserver_id_ = 0;
  SenderOptions options_;
  bool welcomed_ = false;
  std::string server_error_;  // the text of an ERROR the server sent, if any
  std::optional<std::uint32_t> last_swapped_;
  std::optional<TileDeltaEncoder> deltas_;  // with options_.codec
};

}  // namespace l2::viz
