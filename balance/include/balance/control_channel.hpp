// What moves the control lines (control_messages.hpp) between a pipeserver and the coordinator:
// a stream socket on one machine (a socket pair, one end inherited by the pipeserver process),
// or MPI messages in an MPI run (mpi_link/include/mpi_link/mpi_control_channel.hpp).
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include "balance/control_messages.hpp"
#include "base/fd.hpp"

namespace l2 {

class ControlChannel {
 public:
  virtual ~ControlChannel() = default;
  // Throws ControlError when the peer is gone.
  virtual void send_line(const std::string& line) = 0;
  // The next line without its newline; nullopt when none came within `timeout`. Throws
  // ControlError when the peer closed or sent a line longer than kMaxControlLine.
  virtual std::optional<std::string> receive_line(std::chrono::milliseconds timeout) = 0;
};

// A LAYOUT line of kMaxControlTiles tiles fits with room to spare.
inline constexpr std::size_t kMaxControlLine = 4u << 20;

// One end of a stream socket.
class SocketControlChannel final : public ControlChannel {
 public:
  explicit SocketControlChannel(Fd socket) : fd_(std::move(socket)) {}
  void send_line(const std::string& line) override;
  std::optional<std::string> receive_line(std::chrono::milliseconds timeout) override;
  int fd() const { return fd_.get(); }

 private:
  Fd fd_;
  std::string pending_;  // bytes after the last full line read
};

// Both ends of a new socket pair. Neither is close-on-exec: a child started with one keeps it.
std::pair<SocketControlChannel, SocketControlChannel> control_socket_pair();

}  // namespace l2
