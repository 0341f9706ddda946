// The back-channel behind one interface: READY from the Lightning-2 to a host, and the host's
// wait for it (spec §6). The serial line (back_channel.hpp: a tty, or a pty on one machine) is
// one implementation; one channel per host, used from one thread at a time.
#pragma once

#include <chrono>
#include <cstdint>

#include "base/result.hpp"

namespace l2 {

struct BackChannelCounts;

// The READY a host's wait took: its frame and how many SYNC? requests it cost. A wait that
// ran out is a Failure instead, whose reason names the frame, the line and the retries.
struct ReadyAck {
  std::uint32_t frame = 0;  // the frame accepted (modulo 10^6): the one awaited, or a newer one
  int retries = 0;          // SYNC? requests it took
};

class ReadyChannel {
 public:
  virtual ~ReadyChannel() = default;

  // Lightning-2 end: announces that `frame` is on the displays, never waiting; false when it
  // was dropped (the host recovers by asking).
  virtual bool send_ready(std::uint64_t frame) = 0;
  // Lightning-2 end: answers the host's requests for `duration`; returns how many.
  virtual int serve(std::chrono::milliseconds duration) = 0;
  // Host end: waits for READY `expected` (or newer), asking again `retries` times.
  virtual Result<ReadyAck> wait_ready(std::uint64_t expected, std::chrono::milliseconds timeout,
                                      int retries) = 0;
  // Host end: asks for the last READY without waiting for it.
  virtual void send_sync_request(std::uint64_t expected) = 0;

  virtual const BackChannelCounts& counts() const = 0;
};

}  // namespace l2
