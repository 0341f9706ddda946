// The READY protocol of the serial back-channel (spec §6.3), as pure logic: the byte layout of
// a message and an incremental parser that recovers from line noise. No I/O here; the wire is in
// back_channel.hpp. docs/ready-protocol.md is the human description of the same rules.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace l2 {

// Every message is one fixed-length ASCII line, so a person can read it in a terminal:
//   "READY 000123 6E\r\n"  verb, space, 6 decimal digits, space, 2 uppercase hex digits, CR LF.
inline constexpr std::size_t kMessageBytes = 17;
inline constexpr std::size_t kChecksummedBytes = 12;  // verb, space and the six digits
// Frame numbers travel modulo 10^6 (six digits): about 4.6 hours at 60 Hz before they wrap.
inline constexpr std::uint32_t kFrameModulus = 1'000'000;

enum class MessageKind : std::uint8_t {
  Ready,        // emulator -> host: frame `frame` was swapped onto the displays
  SyncRequest,  // host -> emulator: "SYNC?": please repeat your last READY
};

struct Message {
  MessageKind kind = MessageKind::Ready;
  std::uint32_t frame = 0;  // 0 .. kFrameModulus - 1
  friend bool operator==(const Message&, const Message&) = default;
};

// CRC-8, polynomial x^8 + x^2 + x + 1 (0x07), initial 0, no reflection, no final XOR
// ("CRC-8/SMBUS"; check value of "123456789" is 0xF4).
std::uint8_t crc8(std::string_view bytes);

// The 17 bytes of a message; the frame is reduced modulo kFrameModulus.
std::string format_message(MessageKind kind, std::uint64_t frame);

// "READY 000123" — the line without checksum and CR LF, for logs.
std::string to_string(const Message& message);

// What the parser threw away. Together with the decoded messages these account for every byte
// fed: messages * 17 + bad_checksums * 17 + noise_bytes.
struct ParserCounts {
  std::uint64_t messages = 0;       // well-formed messages with a matching checksum
  std::uint64_t noise_bytes = 0;    // bytes outside any message, including lost partial messages
  std::uint64_t resyncs = 0;        // started messages abandoned because a byte broke the format
  std::uint64_t bad_checksums = 0;  // complete, well-formed lines whose checksum did not match
};

// Feeds arbitrary bytes, calls back once per valid message. A message may arrive split across
// any number of feed() calls. Resynchronisation rule: outside a message every byte except a
// start marker ('R' or 'S') is noise; inside a message the first byte that does not fit the
// layout abandons it, and that byte is examined again as a possible start marker. The markers
// appear nowhere else in a valid message, so no valid message that follows noise is ever lost.
class MessageParser {
 public:
  template <typename OnMessage>
  void feed(std::span<const std::uint8_t> bytes, OnMessage&& on_message) {
    for (std::uint8_t byte : bytes) {
      if (consume(byte)) on_message(last_);
    }
  }
  std::vector<Message> feed(std::span<const std::uint8_t> bytes);
  std::vector<Message> feed(std::string_view bytes);

  const ParserCounts& counts() const { return counts_; }
  // Bytes of a message begun but not finished (0 when hunting for a start marker).
  std::size_t pending() const { return length_; }

 private:
  bool consume(std::uint8_t byte);  // true when `byte` completed a valid message (in last_)
  bool fits(std::uint8_t byte) const;
  bool finish();

  std::array<std::uint8_t, kMessageBytes> line_{};
  std::size_t length_ = 0;
  Message last_;
  ParserCounts counts_;
};

}  // namespace l2
