// TUIO over UDP (`l2wall run --tuio [ADDR:]PORT`): the socket, bound to the address given
// (loopback unless told), read without waiting from the run's loop. It owns the socket and the
// cursors said so far; each datagram waiting is decoded (osc_packet.hpp) and its cursor
// messages taken (tuio_cursors.hpp). A datagram that is not OSC, or too long, is dropped and
// counted; nothing that arrives can make it wait, allocate without bound or end the run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/fd.hpp"
#include "touch/tuio_cursors.hpp"

namespace l2 {

class TuioReceiver {
 public:
  // Throws NetError in one line when the address cannot be bound (in use, not this machine's).
  TuioReceiver(const std::string& host, std::uint16_t port);

  std::uint16_t port() const;  // the one bound (port 0 asks for a free one)
  // The frames committed by the datagrams waiting now, oldest first. At most
  // kMaxDatagramsPerPoll are read a call, so a flood cannot hold the frame loop.
  std::vector<CursorFrame> poll();

  long dropped_packets() const { return dropped_packets_; }
  long dropped_messages() const { return cursors_.dropped_messages(); }

  static constexpr int kMaxDatagramsPerPoll = 64;

 private:
  Fd fd_;
  TuioCursors cursors_;
  std::vector<std::uint8_t> buffer_;
  long dropped_packets_ = 0;
};

}  // namespace l2
