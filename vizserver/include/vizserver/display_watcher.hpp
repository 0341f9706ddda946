// The watcher's end of the display stream (display_stream.hpp): l2wall accepts the compositing
// server's connection, reads which port it listens on, and then takes its swapped frames in
// order. A reader thread drains the socket as frames arrive, so a frame of several megabytes
// never holds up the caller's own loop; it holds at most `max_held` complete frames and then
// stops reading, so a slow caller slows the server (TCP flow control) instead of growing memory.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "base/result.hpp"
#include "base/socket.hpp"
#include "vizserver/compositing_server.hpp"
#include "vizserver/display_stream.hpp"
#include "vizserver/picture_pool.hpp"

namespace l2::viz {

// Waits up to `timeout` for a connection on `listener`; an empty Fd if none came. Short
// timeouts let the caller check on the server process in between.
Fd accept_within(const Fd& listener, std::chrono::milliseconds timeout);

// Reads the first message of a display stream, which must be LISTENING. Throws NetError naming
// `peer` (ERROR text included, e.g. the server could not bind its port).
Listening read_listening(int fd, Clock::time_point deadline, const std::string& peer);

class DisplayWatcher {
 public:
  // Takes over a connected stream whose LISTENING was read and starts the reader thread.
  // `display_count` is what LISTENING announced: a frame with more DISPLAY messages breaks the
  // protocol (without the bound a stream could fill memory before its SHOWN). io_timeout bounds
  // the rest of a message once its first byte arrived.
  DisplayWatcher(Fd fd, std::string peer, std::uint32_t display_count, std::size_t max_held = 4,
                 std::chrono::milliseconds io_timeout = std::chrono::seconds(10));
  ~DisplayWatcher();  // stops and joins the reader
  DisplayWatcher(const DisplayWatcher&) = delete;
  DisplayWatcher& operator=(const DisplayWatcher&) = delete;

  // Frame `frame` once every display of it arrived; it and every older frame leave the stream.
  // nullptr if it did not arrive within `timeout`. Throws NetError when the stream ended first
  // (the server's ERROR text, or how the connection closed), broke the protocol, or went past
  // `frame` without it.
  FramePtr take(std::uint32_t frame, std::chrono::milliseconds timeout);

  // Failed, with why the stream ended, once it has (ok while it runs); and whether that was
  // the server's own ERROR (a server that says why it stops is not one that died).
  Status ended() const;
  bool ended_with_error_message() const;

  // Tells the server that pipeserver `pipeserver` is gone (LOST; a server started with
  // --survive-loss stops waiting for it). Throws NetError when the stream cannot take it.
  void send_lost(std::uint32_t pipeserver);

 private:
  void run();
  void read_stream();
  // Reads exactly n bytes. At a message boundary a clean close returns false; in the middle of
  // a message it throws. Returns false when asked to stop.
  bool read_exact(std::uint8_t* data, std::size_t n, bool at_boundary, const char* what);
  void publish(ComposedFrame frame);
  void finish(std::string reason, bool error_message);

  Fd fd_;
  std::string peer_;
  std::uint32_t display_count_;
  std::size_t max_held_;
  std::chrono::milliseconds io_timeout_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::uint32_t, FramePtr> held_;
  std::optional<std::uint32_t> last_arrived_;
  std::optional<std::string> ended_;
  bool error_message_ = false;
  std::atomic<bool> stop_{false};
  std::shared_ptr<PicturePool> pictures_;  // received frames' pictures, reused
  std::thread thread_;
};

}  // namespace l2::viz
