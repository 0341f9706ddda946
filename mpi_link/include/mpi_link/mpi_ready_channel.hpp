// The back-channel as MPI messages (the MPI backend of ready_channel.hpp): the 17-byte READY
// and SYNC? lines of docs/ready-protocol.md, one line per message. The protocol (waits,
// retries, counts) is ReadyLine's, as on the serial line; this only moves the lines.
#pragma once

#include <string>

#include "mpi_link/mpi_outbox.hpp"
#include "sync_backchannel/ready_line.hpp"

namespace l2 {

class MpiReadyChannel final : public ReadyLine {
 public:
  // `peer`: the rank at the other end (the coordinator for a host, a host for the
  // coordinator); `name` is how a wait that timed out names the line ("MPI rank 0").
  MpiReadyChannel(int peer, std::string name)
      : peer_(peer), name_(std::move(name)), outbox_(peer) {}

 private:
  bool send_line(const std::string& line, MessageKind kind) override;
  bool receive(MessageKind awaited, std::chrono::milliseconds timeout) override;
  const std::string& line_name() const override { return name_; }

  int peer_;
  std::string name_;
  // A READY to a pipeserver rank that has just died is never taken: it must not hold the
  // coordinator (MpiOutbox).
  MpiOutbox outbox_;
};

}  // namespace l2
