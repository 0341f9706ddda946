#include "mpi_link/mpi_ready_channel.hpp"

#include <mpi.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "mpi_link/mpi_wire.hpp"

namespace l2 {
namespace {

// READY and SYNC? travel under tags of their own, so each end takes only what it waits for.
int tag_of(MessageKind kind) {
  return kind == MessageKind::Ready ? mpi_wire::kReady : mpi_wire::kSync;
}

}  // namespace

bool MpiReadyChannel::send_line(const std::string& line, MessageKind kind) {
  return outbox_.send(line, tag_of(kind));
}

bool MpiReadyChannel::receive(MessageKind awaited, std::chrono::milliseconds timeout) {
  outbox_.reap();
  const int tag = tag_of(awaited);
  bool any = false;
  while (const auto bytes = mpi_wire::waiting(peer_, tag)) {
    std::vector<std::uint8_t> line(static_cast<std::size_t>(*bytes));
    MPI_Recv(line.data(), *bytes, MPI_BYTE, peer_, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    feed(line);
    any = true;
  }
  // MPI has no wait with a timeout on a probe: nothing yet, look again shortly.
  if (!any && timeout.count() > 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
  return any;
}

}  // namespace l2
