#include "mpi_link/mpi_control_channel.hpp"

#include <fmt/format.h>

#include <thread>
#include <vector>

#include "mpi_link/mpi_wire.hpp"

namespace l2 {

void MpiControlChannel::send_line(const std::string& line) {
  if (line.size() > kMaxControlLine)
    throw ControlError(
        fmt::format("control channel: a line longer than {} bytes", kMaxControlLine));
  if (!outbox_.send(line, tag_))
    throw ControlError(fmt::format("control channel: sending to rank {} failed", peer_));
}

std::optional<std::string> MpiControlChannel::receive_line(std::chrono::milliseconds timeout) {
  outbox_.reap();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (const auto bytes = mpi_wire::waiting(peer_, tag_)) {
      if (static_cast<std::size_t>(*bytes) > kMaxControlLine)
        throw ControlError(
            fmt::format("control channel: a line longer than {} bytes", kMaxControlLine));
      std::string line(static_cast<std::size_t>(*bytes), '\0');
      if (MPI_Recv(line.data(), *bytes, MPI_CHAR, peer_, tag_, MPI_COMM_WORLD, MPI_STATUS_IGNORE) !=
          MPI_SUCCESS)
        throw ControlError(fmt::format("control channel: receiving from rank {} failed", peer_));
      return line;
    }
    // MPI has no wait with a timeout on a probe: nothing yet, look again shortly.
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

}  // namespace l2
