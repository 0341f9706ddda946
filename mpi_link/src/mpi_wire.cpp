#include "mpi_link/mpi_wire.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace l2::mpi_wire {
namespace {

void check(int code, const char* call, int peer) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(
      fmt::format("{} with rank {}: {}", call, peer, std::string(text, length)));
}

// Waits for `request` to complete: at first as MPI_Wait would, then looking every 100 us.
void wait_sleeping(MPI_Request& request, const char* call, int peer) {
  const auto spin_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(1);
  for (;;) {
    int done = 0;
    check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), call, peer);
    if (done) return;
    if (std::chrono::steady_clock::now() >= spin_until)
      std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

}  // namespace

void send_bytes(std::span<const std::uint8_t> bytes, int to, int tag) {
  MPI_Request request = MPI_REQUEST_NULL;
  check(MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD,
                  &request),
        "MPI_Isend", to);
  wait_sleeping(request, "MPI_Isend", to);
}

void receive_bytes(std::span<std::uint8_t> into, int from, int tag) {
  MPI_Request request = MPI_REQUEST_NULL;
  check(MPI_Irecv(into.data(), static_cast<int>(into.size()), MPI_BYTE, from, tag, MPI_COMM_WORLD,
                  &request),
        "MPI_Irecv", from);
  wait_sleeping(request, "MPI_Irecv", from);
}

void send(const Record& record, int to, int tag) {
  check(MPI_Send(record.data(), static_cast<int>(record.size()), MPI_INT64_T, to, tag,
                 MPI_COMM_WORLD),
        "MPI_Send", to);
}

std::optional<int> waiting(int from, int tag) {
  int flag = 0;
  MPI_Status status;
  check(MPI_Iprobe(from, tag, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe", from);
  if (!flag) return std::nullopt;
  int bytes = 0;
  MPI_Get_count(&status, MPI_BYTE, &bytes);
  return bytes;
}

Record receive(int from, int tag) {
  MPI_Status status;
  check(MPI_Probe(from, tag, MPI_COMM_WORLD, &status), "MPI_Probe", from);
  int count = 0;
  MPI_Get_count(&status, MPI_INT64_T, &count);
  Record r(static_cast<std::size_t>(count));
  check(MPI_Recv(r.data(), count, MPI_INT64_T, status.MPI_SOURCE, tag, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv", status.MPI_SOURCE);
  return r;
}

Record receive_watched(int from, int tag, const std::function<void()>& watch) {
  while (!waiting(from, tag)) {
    watch();
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  return receive(from, tag);
}

std::int64_t Reader::next() {
  if (at_ >= r_.size()) throw std::runtime_error("MPI record shorter than its contents say");
  return r_[at_++];
}

std::size_t Reader::count(std::size_t words) {
  const std::int64_t n = next();
  const std::size_t left = r_.size() - at_;
  if (n < 0 || static_cast<std::uint64_t>(n) > left / std::max<std::size_t>(words, 1))
    throw std::runtime_error(
        fmt::format("MPI record: a count of {} items where {} words are left", n, left));
  return static_cast<std::size_t>(n);
}

}  // namespace l2::mpi_wire
