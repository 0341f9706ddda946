// The READY protocol on a serial line (spec §6, docs/ready-protocol.md). The emulator end sends
// READY after every group swap and answers SYNC? requests; the host end waits for the READY of
// the frame it needs, asking again with SYNC? when a READY is late or was lost.
// One BackChannel per line, used from one thread at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "sync_backchannel/ready_channel.hpp"
#include "sync_backchannel/ready_protocol.hpp"
#include "sync_backchannel/serial_port.hpp"

namespace l2 {

inline constexpr std::chrono::milliseconds kDefaultReadyTimeout{200};
inline constexpr int kDefaultReadyRetries = 3;
// Bounds the host's SYNC? write; the emulator end never waits (see send_ready).
inline constexpr std::chrono::milliseconds kWriteTimeout{100};

struct BackChannelCounts {
  ParserCounts parser;                // decoded, noise bytes, resyncs, bad checksums
  std::uint64_t ready_sent = 0;       // READY lines sent (including answers to SYNC?)
  std::uint64_t ready_dropped = 0;    // of those, not (wholly) taken by a full line
  std::uint64_t sync_sent = 0;        // SYNC? requests written (host retries)
  std::uint64_t sync_answered = 0;    // SYNC? requests answered with the last READY
  std::uint64_t sync_unanswered = 0;  // SYNC? requests before any READY existed
  std::uint64_t wait_timeouts = 0;    // single waits that ran out (each followed by a retry)
  std::uint64_t stale = 0;            // READY for a frame older than the one awaited
  std::uint64_t duplicates = 0;       // READY repeating the frame accepted last
  std::uint64_t ahead = 0;            // READY newer than awaited, accepted
  std::uint64_t unexpected = 0;       // valid message of the wrong direction
};

// "decoded 12, noise bytes 3, resyncs 1, bad checksums 0, stale 0, duplicates 1, ..."
std::string to_string(const BackChannelCounts& counts);

enum class WaitStatus : std::uint8_t { Ok, Timeout };

struct WaitResult {
  WaitStatus status = WaitStatus::Timeout;
  std::uint32_t frame = 0;  // the READY frame accepted (Ok) or the one awaited (Timeout)
  int retries = 0;          // SYNC? requests it took
  std::string error;        // one line for the user when status == Timeout
  bool ok() const { return status == WaitStatus::Ok; }
};

// The serial-line implementation of ReadyChannel.
class BackChannel final : public ReadyChannel {
 public:
  explicit BackChannel(SerialPort& port) : port_(port) {}

  // Emulator end: announces that `frame` (taken modulo 10^6) is on the displays. Never waits:
  // when the line is full because the host stopped reading, the READY (or its tail) is dropped
  // and counted, and false is returned; the host recovers through SYNC?. A stuck host must not
  // hold up the swap of every display.
  bool send_ready(std::uint64_t frame) override;

  // Emulator end: reads for `duration`, answering every SYNC? with the last READY sent.
  // Returns how many requests were answered.
  int serve(std::chrono::milliseconds duration) override;

  // Host end: waits for READY `expected` (modulo 10^6). Each wait lasts `timeout`; when one
  // runs out the host sends "SYNC? <expected>" and waits again, up to `retries` times. A READY
  // newer than `expected` is accepted (the emulator is past our frame); older ones are ignored.
  WaitResult wait_ready(std::uint64_t expected,
                        std::chrono::milliseconds timeout = kDefaultReadyTimeout,
                        int retries = kDefaultReadyRetries) override;

  // Host end: asks for the last READY without waiting for it.
  void send_sync_request(std::uint64_t expected) override;

  const BackChannelCounts& counts() const override;
  const std::string& name() const { return port_.name(); }

 private:
  // Reads once (up to `timeout`) and queues what it decodes; false when nothing arrived.
  bool pump(std::chrono::milliseconds timeout);
  // Whether READY `frame` satisfies a wait for `expected`; counts the ones it ignores.
  bool accept(std::uint32_t frame, std::uint32_t expected);

  SerialPort& port_;
  MessageParser parser_;
  std::deque<Message> inbox_;
  std::optional<std::uint32_t> last_sent_;      // emulator: the READY SYNC? repeats
  std::optional<std::uint32_t> last_accepted_;  // host: to tell duplicates from stale READYs
  mutable BackChannelCounts counts_;
};

}  // namespace l2
