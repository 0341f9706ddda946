#include "cluster/mpi_control_channel.hpp"

#include <fmt/format.h>

#include <thread>
#include <vector>

#include "cluster/mpi_wire.hpp"

namespace l2 {

MpiControlChannel::~MpiControlChannel() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) {
    // Too late to ask MPI: the sends' buffers are left to the process's end.
    for (Sending& s : sending_) static_cast<void>(s.line.release());
    return;
  }
  reap();
  // A line the peer never took (it ended first): the send may still complete later, so its
  // buffer is left to the process's end.
  for (Sending& s : sending_) {
    MPI_Request_free(&s.request);
    static_cast<void>(s.line.release());
  }
}

void MpiControlChannel::reap() {
  while (!sending_.empty()) {
    int done = 0;
    MPI_Test(&sending_.front().request, &done, MPI_STATUS_IGNORE);
    if (!done) return;
    sending_.pop_front();
  }
}

void MpiControlChannel::send_line(const std::string& line) {
  reap();
  if (line.size() > kMaxControlLine)
    throw ControlError(
        fmt::format("control channel: a line longer than {} bytes", kMaxControlLine));
  Sending s{std::make_unique<std::string>(line), MPI_REQUEST_NULL};
  if (MPI_Isend(s.line->data(), static_cast<int>(s.line->size()), MPI_CHAR, peer_, tag_,
                MPI_COMM_WORLD, &s.request) != MPI_SUCCESS)
    throw ControlError(fmt::format("control channel: sending to rank {} failed", peer_));
  sending_.push_back(std::move(s));
}

std::optional<std::string> MpiControlChannel::receive_line(std::chrono::milliseconds timeout) {
  reap();
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
