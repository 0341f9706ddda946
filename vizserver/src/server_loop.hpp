// The compositing server's network loop: one thread, one poll() over the listening socket, a
// wake-up pipe and every connection. It owns all sockets and the FrameAssembler; what callers
// may see goes through ServerShared under its mutex.
#pragma once

#include <array>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "base/socket.hpp"
#include "viz_link/tile_delta.hpp"
#include "viz_link/wire.hpp"
#include "vizserver/compositing_server.hpp"
#include "vizserver/frame_assembler.hpp"

namespace l2::viz {

struct ServerShared {
  mutable std::mutex mutex;
  std::condition_variable changed;
  std::deque<FramePtr> recent;  // the last recent_frames swapped frames
  std::optional<std::uint32_t> last_swapped;
  std::optional<std::string> failure;
  std::vector<std::string> errors;  // the first kKeptErrors, and the failure
  std::uint64_t error_count = 0;    // every connection error
  StripErrorCounts counts;
  bool ended = false;     // the loop has returned
  bool all_left = false;  // ... because every pipeserver finished and disconnected
  bool stop = false;      // stop() asked the loop to end
  std::vector<int> lose;  // lose() asked, not yet taken by the loop
};

class ServerLoop {
 public:
  ServerLoop(const ServerOptions& options, Fd listener, std::uint16_t port,
             std::shared_ptr<ServerShared> shared, std::function<void(const FramePtr&)> on_swap);
  ~ServerLoop();  // stops and joins

  void stop();
  void lose(int pipeserver);  // CompositingServer::lose_pipeserver, from any thread

 private:
  // One peer. Reads go header (12 bytes) -> fixed part -> variable part (pixels, text), each
  // into its final buffer, so a tile's pixels are received once and never copied again.
  struct Connection {
    Fd fd;
    std::string peer;
    int pipeserver = -1;  // its id once HELLO was accepted
    MessageHead head{Protocol::Tiles};
    std::optional<TileHeader> tile;
    std::optional<TileDeltaDecoder> deltas;  // its TILE_DELTAs' tiles, from the first
    std::vector<std::uint8_t> body;
    std::size_t body_got = 0;
    bool body_ready = false;
    std::string out;  // queued server -> peer bytes
    std::size_t out_sent = 0;
    Clock::time_point connected, last_activity;
    std::optional<std::uint32_t> waiting_frame;  // the frame last seen waiting for it
    Clock::time_point waiting_since;
    bool dead = false;
  };

  void run();
  void accept_all();
  // When the strangers are too many: reads what each has sent (a pipeserver's HELLO may be
  // waiting), then closes the oldest that still has not said HELLO.
  void make_room_for_a_stranger();
  std::size_t count_strangers(Connection** oldest) const;
  void read_some(Connection& c);
  bool advance(Connection& c);  // parse what arrived; false when the connection was closed
  void dispatch(Connection& c);
  void on_hello(Connection& c);
  void flush(Connection& c);
  void queue(Connection& c, std::span<const std::uint8_t> bytes);
  void send_error(Connection& c, const std::string& text);
  // Closes c. With a reason: a protocol error (ends the run if c is a pipeserver).
  void close(Connection& c, const std::optional<std::string>& reason);
  void fail(const std::string& line);
  void log_error(const std::string& line);
  std::string who(const Connection& c) const;
  void publish_swaps();
  void check_timers(Clock::time_point now);
  // A pipeserver silent in the middle of a message: the stall timeout ends it whether or not a
  // frame waits for it (with one pipeserver, none does).
  bool stalled_mid_message(const Connection& c, Clock::time_point now);
  std::string message_progress(const Connection& c) const;
  void shut_down();
  // The wake-up pipe was readable: drains it; true when stop() asked, else takes lose()s.
  bool woken();
  // A pipeserver's connection ended (EOF, reset): with survive_losses it awaits lose().
  void peer_closed(Connection& c, std::optional<std::string> reason);

  ServerOptions options_;
  int lost_before_hello_ = 0;  // lost without ever saying HELLO: not awaited
  Fd listener_;
  std::uint16_t port_;
  std::shared_ptr<ServerShared> shared_;
  std::function<void(const FramePtr&)> on_swap_;
  FrameAssembler assembler_;
  std::vector<std::unique_ptr<Connection>> conns_;
  int hellos_ = 0;
  std::uint64_t strangers_evicted_ = 0;  // closed to make room: too many without HELLO
  std::optional<std::string> failure_;
  Clock::time_point started_;
  Fd wake_read_, wake_write_;
  std::thread thread_;
};

}  // namespace l2::viz
