// The load balancer's control channel (balance/control_channel.hpp) as MPI messages: the TIMES
// and LAYOUT lines between a pipeserver rank and the coordinator, one line per message under a
// tag of their own (mpi_wire::kControl), so neither end takes another message for one; a vnc
// run's desktop lines the same way under mpi_wire::kWindows.
#pragma once

#include <mpi.h>

#include <chrono>
#include <optional>
#include <string>

#include "balance/control_channel.hpp"
#include "mpi_link/mpi_outbox.hpp"

namespace l2 {

class MpiControlChannel final : public ControlChannel {
 public:
  // `peer`: the rank at the other end; `tag`: the channel's own (mpi_wire::kControl for
  // balancing, kWindows for a vnc run's desktop). MPI must be initialised (MpiSession) and stay
  // so while this channel lives.
  explicit MpiControlChannel(int peer, int tag) : peer_(peer), tag_(tag), outbox_(peer) {}

  // Does not wait for the peer to take the line: a blocking send of a long LAYOUT line would
  // wait for a receive the peer posts only after the READY this process is yet to send.
  void send_line(const std::string& line) override;
  std::optional<std::string> receive_line(std::chrono::milliseconds timeout) override;

 private:
  int peer_;
  int tag_;
  MpiOutbox outbox_;
};

}  // namespace l2
