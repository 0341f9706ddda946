// The compositing server's end of the display stream (display_stream.hpp): connects to the
// watcher that started it, says which port it listens on, then sends every swapped frame.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "base/socket.hpp"
#include "vizserver/display_stream.hpp"
#include "vizserver/frame_assembler.hpp"

namespace l2::viz {

class DisplaySender {
 public:
  // Connects to the watcher at host:port (it listens before it starts us). io_timeout bounds
  // every send: a watcher that stops reading for that long is gone. Throws NetError
  // "display stream HOST:PORT: ...".
  static DisplaySender connect(const std::string& host, std::uint16_t port,
                               std::chrono::milliseconds io_timeout = std::chrono::seconds(60));

  // The first message: the port the pipeservers connect to.
  void send_listening(const Listening& listening);

  // DISPLAY for every display of the frame (no copy: straight from its pictures), then SHOWN.
  void send_frame(const ComposedFrame& frame);
  // The failure line as ERROR, before the server exits. Best effort: never throws.
  void send_error(const std::string& text) noexcept;
  // The pipeservers the watcher said are lost (LOST messages), as they arrive; never blocks.
  // Throws NetError for anything else the watcher sends, or a LOST cut short.
  std::vector<std::uint32_t> take_lost();
  // True once the watcher has closed its end (it sends nothing but LOST, which take_lost()
  // reads first, so anything else readable is EOF).
  bool watcher_gone() const;

  const std::string& peer() const { return peer_; }

 private:
  DisplaySender(Fd fd, std::string peer, std::chrono::milliseconds io_timeout)
      : fd_(std::move(fd)), peer_(std::move(peer)), io_timeout_(io_timeout) {}

  Fd fd_;
  std::string peer_;
  std::chrono::milliseconds io_timeout_;
};

}  // namespace l2::viz
