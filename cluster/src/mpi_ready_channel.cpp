#include "cluster/mpi_ready_channel.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <thread>
#include <vector>

#include "cluster/mpi_wire.hpp"

namespace l2 {
namespace {

using Clock = std::chrono::steady_clock;

void send_line(const std::string& line, int to, int tag) {
  MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

}  // namespace

const BackChannelCounts& MpiReadyChannel::counts() const {
  counts_.parser = parser_.counts();
  return counts_;
}

bool MpiReadyChannel::send_ready(std::uint64_t frame) {
  last_sent_ = static_cast<std::uint32_t>(frame % kFrameModulus);
  ++counts_.ready_sent;
  send_line(format_message(MessageKind::Ready, frame), peer_, mpi_wire::kReady);
  return true;
}

void MpiReadyChannel::send_sync_request(std::uint64_t expected) {
  ++counts_.sync_sent;
  send_line(format_message(MessageKind::SyncRequest, expected), peer_, mpi_wire::kSync);
}

bool MpiReadyChannel::pump(int tag) {
  bool any = false;
  while (const auto bytes = mpi_wire::waiting(peer_, tag)) {
    std::vector<std::uint8_t> line(static_cast<std::size_t>(*bytes));
    MPI_Recv(line.data(), *bytes, MPI_BYTE, peer_, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    parser_.feed(std::span<const std::uint8_t>(line),
                 [&](const Message& m) { inbox_.push_back(m); });
    any = true;
  }
  return any;
}

int MpiReadyChannel::serve(std::chrono::milliseconds duration) {
  const auto deadline = Clock::now() + duration;
  int answered = 0;
  do {
    pump(mpi_wire::kSync);
    while (!inbox_.empty()) {
      const Message m = inbox_.front();
      inbox_.pop_front();
      if (m.kind != MessageKind::SyncRequest) {
        ++counts_.unexpected;
      } else if (!last_sent_) {
        ++counts_.sync_unanswered;
      } else {
        ++counts_.sync_answered;
        ++answered;
        send_ready(*last_sent_);
      }
    }
  } while (Clock::now() < deadline);
  return answered;
}

// As BackChannel::accept: a newer READY than awaited counts (the emulator is past our frame).
bool MpiReadyChannel::accept(std::uint32_t frame, std::uint32_t expected) {
  const std::uint32_t distance = (frame + kFrameModulus - expected) % kFrameModulus;
  if (distance == 0) return true;
  if (distance < kFrameModulus / 2) {
    ++counts_.ahead;
    return true;
  }
  if (last_accepted_ == frame) {
    ++counts_.duplicates;
  } else {
    ++counts_.stale;
  }
  return false;
}

WaitResult MpiReadyChannel::wait_ready(std::uint64_t expected_frame,
                                       std::chrono::milliseconds timeout, int retries) {
  const auto expected = static_cast<std::uint32_t>(expected_frame % kFrameModulus);
  for (int attempt = 0;; ++attempt) {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
      while (!inbox_.empty()) {
        const Message m = inbox_.front();
        inbox_.pop_front();
        if (m.kind != MessageKind::Ready) {
          ++counts_.unexpected;
        } else if (accept(m.frame, expected)) {
          last_accepted_ = m.frame;
          return WaitResult{WaitStatus::Ok, m.frame, attempt, {}};
        }
      }
      if (Clock::now() >= deadline) break;
      if (!pump(mpi_wire::kReady)) std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    ++counts_.wait_timeouts;
    if (attempt == retries) {
      return WaitResult{
          WaitStatus::Timeout, expected, attempt,
          fmt::format("no READY for frame {:06d} on {} after {} SYNC? retries ({} waits of {} ms)",
                      expected, name_, retries, retries + 1, timeout.count())};
    }
    send_sync_request(expected);
  }
}

}  // namespace l2
