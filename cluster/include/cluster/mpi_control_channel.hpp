// The load balancer's control channel (balance/control_channel.hpp) as MPI messages: the TIMES
// and LAYOUT lines between a pipeserver rank and the coordinator, one line per message under a
// tag of their own (mpi_wire::kControl), so neither end takes another message for one; a vnc
// run's desktop lines the same way under mpi_wire::kWindows.
#pragma once

#include <mpi.h>

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "balance/control_channel.hpp"

namespace l2 {

class MpiControlChannel final : public ControlChannel {
 public:
  // `peer`: the rank at the other end; `tag`: the channel's own (mpi_wire::kControl for
  // balancing, kWindows for a vnc run's desktop). MPI must be initialised (MpiSession) and stay
  // so while this channel lives.
  explicit MpiControlChannel(int peer, int tag) : peer_(peer), tag_(tag) {}
  ~MpiControlChannel() override;
  MpiControlChannel(const MpiControlChannel&) = delete;
  MpiControlChannel& operator=(const MpiControlChannel&) = delete;

  // Does not wait for the peer to take the line: a blocking send of a long LAYOUT line would
  // wait for a receive the peer posts only after the READY this process is yet to send.
  void send_line(const std::string& line) override;
  std::optional<std::string> receive_line(std::chrono::milliseconds timeout) override;

 private:
  struct Sending {
    std::unique_ptr<std::string> line;  // stays put until the send completes
    MPI_Request request = MPI_REQUEST_NULL;
  };
  // Forgets the sends that completed.
  void reap();

  int peer_;
  int tag_;
  std::deque<Sending> sending_;
};

}  // namespace l2
