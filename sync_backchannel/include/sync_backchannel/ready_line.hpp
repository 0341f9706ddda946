// The READY protocol itself (spec §6, docs/ready-protocol.md), over any transport of its lines:
// the emulator end's READY and answers to SYNC?, the host end's wait with retries, and the
// counts. A transport (the serial line of back_channel.hpp, MPI messages in mpi_link/) only
// moves the 17-byte lines; what they mean is decided here, once.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>

#include "sync_backchannel/ready_channel.hpp"
#include "sync_backchannel/ready_protocol.hpp"

namespace l2 {

inline constexpr std::chrono::milliseconds kDefaultReadyTimeout{200};
inline constexpr int kDefaultReadyRetries = 3;

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

class ReadyLine : public ReadyChannel {
 public:
  // Emulator end: announces that `frame` (taken modulo 10^6) is on the displays. Never waits:
  // a READY the transport could not take is counted as dropped and false is returned; the
  // host recovers through SYNC?. A stuck host must not hold up the swap of every display.
  bool send_ready(std::uint64_t frame) final;

  // Emulator end: reads for `duration`, answering every SYNC? with the last READY sent.
  // Returns how many requests were answered.
  int serve(std::chrono::milliseconds duration) final;

  // Host end: waits for READY `expected` (modulo 10^6). Each wait lasts `timeout`; when one
  // runs out the host sends "SYNC? <expected>" and waits again, up to `retries` times. A READY
  // newer than `expected` is accepted (the emulator is past our frame); older ones are ignored.
  // When the last wait runs out: a Failure naming the frame, the line and the retries.
  Result<ReadyAck> wait_ready(std::uint64_t expected,
                              std::chrono::milliseconds timeout = kDefaultReadyTimeout,
                              int retries = kDefaultReadyRetries) final;

  // Host end: asks for the last READY without waiting for it.
  void send_sync_request(std::uint64_t expected) final;

  const BackChannelCounts& counts() const final;

 protected:
  // The transport. READY must not wait (false: not wholly sent); SYNC? may, boundedly.
  virtual bool send_line(const std::string& line, MessageKind kind) = 0;
  // Waits up to `timeout` for lines of `awaited`'s kind and hands their bytes to feed();
  // false when nothing arrived.
  virtual bool receive(MessageKind awaited, std::chrono::milliseconds timeout) = 0;
  // How a wait that timed out names the line ("/dev/pts/3", "MPI rank 0 (coordinator)").
  virtual const std::string& line_name() const = 0;

  void feed(std::span<const std::uint8_t> bytes);

 private:
  // Whether READY `frame` satisfies a wait for `expected`; counts the ones it ignores.
  bool accept(std::uint32_t frame, std::uint32_t expected);

  MessageParser parser_;
  std::deque<Message> inbox_;
  std::optional<std::uint32_t> last_sent_;      // emulator: the READY SYNC? repeats
  std::optional<std::uint32_t> last_accepted_;  // host: to tell duplicates from stale READYs
  mutable BackChannelCounts counts_;
};

}  // namespace l2
