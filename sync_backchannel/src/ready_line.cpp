#include "sync_backchannel/ready_line.hpp"

#include <fmt/format.h>

namespace l2 {
namespace {

using Clock = std::chrono::steady_clock;

std::uint32_t reduce(std::uint64_t frame) {
  return static_cast<std::uint32_t>(frame % kFrameModulus);
}

std::chrono::milliseconds left_until(Clock::time_point deadline) {
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() > 0 ? left : std::chrono::milliseconds{0};
}

}  // namespace

std::string to_string(const BackChannelCounts& c) {
  return fmt::format(
      "decoded {}, noise bytes {}, resyncs {}, bad checksums {}, READY sent {}, READY dropped {}, "
      "SYNC? sent {}, "
      "SYNC? answered {}, SYNC? unanswered {}, wait timeouts {}, stale {}, duplicates {}, "
      "ahead {}, unexpected {}",
      c.parser.messages, c.parser.noise_bytes, c.parser.resyncs, c.parser.bad_checksums,
      c.ready_sent, c.ready_dropped, c.sync_sent, c.sync_answered, c.sync_unanswered,
      c.wait_timeouts, c.stale, c.duplicates, c.ahead, c.unexpected);
}

const BackChannelCounts& ReadyLine::counts() const {
  counts_.parser = parser_.counts();
  return counts_;
}

void ReadyLine::feed(std::span<const std::uint8_t> bytes) {
  parser_.feed(bytes, [&](const Message& m) { inbox_.push_back(m); });
}

bool ReadyLine::send_ready(std::uint64_t frame) {
  // Remembered even when dropped: SYNC? repeats it once the host reads again.
  last_sent_ = reduce(frame);
  ++counts_.ready_sent;
  if (send_line(format_message(MessageKind::Ready, frame), MessageKind::Ready)) return true;
  ++counts_.ready_dropped;
  return false;
}

void ReadyLine::send_sync_request(std::uint64_t expected) {
  ++counts_.sync_sent;
  send_line(format_message(MessageKind::SyncRequest, expected), MessageKind::SyncRequest);
}

int ReadyLine::serve(std::chrono::milliseconds duration) {
  const auto deadline = Clock::now() + duration;
  int answered = 0;
  do {
    receive(MessageKind::SyncRequest, left_until(deadline));
    while (!inbox_.empty()) {
      const Message m = inbox_.front();
      inbox_.pop_front();
      if (m.kind != MessageKind::SyncRequest) {
        ++counts_.unexpected;
      } else if (!last_sent_) {
        ++counts_.sync_unanswered;  // nothing swapped yet; the host keeps waiting
      } else {
        ++counts_.sync_answered;
        ++answered;
        send_ready(*last_sent_);
      }
    }
  } while (Clock::now() < deadline);
  return answered;
}

bool ReadyLine::accept(std::uint32_t frame, std::uint32_t expected) {
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

Result<ReadyAck> ReadyLine::wait_ready(std::uint64_t expected_frame,
                                       std::chrono::milliseconds timeout, int retries) {
  const std::uint32_t expected = reduce(expected_frame);
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
          return ReadyAck{m.frame, attempt};
        }
      }
      if (Clock::now() >= deadline) break;
      receive(MessageKind::Ready, left_until(deadline));
    }
    ++counts_.wait_timeouts;
    if (attempt == retries) {
      return Failure{
          fmt::format("no READY for frame {:06d} on {} after {} SYNC? retries ({} waits of {} ms)",
                      expected, line_name(), retries, retries + 1, timeout.count())};
    }
    send_sync_request(expected);
  }
}

}  // namespace l2
